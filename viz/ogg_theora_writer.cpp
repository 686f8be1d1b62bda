#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkOggTheoraWriter.h>

#include <cmath>
#include <cstring>

#include "io/atomic_file.h"
#include "io/input_error.h"
#include "viz/video_writer.h"

namespace mechanist {
namespace {

class OggTheoraWriter final : public VideoWriter {
 public:
  OggTheoraWriter(const std::filesystem::path& path, double fps,
                  const std::filesystem::path& protect)
      : output_(path, protect), fps_(fps) {}

  ~OggTheoraWriter() override {
    if (started_) writer_->End();
  }

  void Add(const Image& frame) override {
    if (!started_) {
      data_->SetDimensions(frame.width, frame.height, 1);
      data_->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
      writer_->SetInputData(data_);
      writer_->SetFileName(output_.temporary().c_str());
      writer_->SetRate(static_cast<int>(std::lround(fps_)));
      writer_->SetQuality(2);  // the best of 0..2
      writer_->SetSubsampling(0);
      writer_->Start();
      started_ = true;
      width_ = frame.width;
      height_ = frame.height;
    }
    if (frame.width != width_ || frame.height != height_) {
      throw InputError(output_.path().string(), "", 0, 0, "video frames differ in size");
    }
    auto* pixels = static_cast<std::uint8_t*>(data_->GetScalarPointer());
    const std::size_t row = static_cast<std::size_t>(frame.width) * 3;
    for (int y = 0; y < frame.height; ++y) {  // VTK's rows go up from the bottom
      std::memcpy(pixels + row * (frame.height - 1 - y), frame.rgb.data() + row * y, row);
    }
    data_->Modified();
    writer_->Write();
    if (writer_->GetErrorCode() != 0) {
      throw InputError(output_.path().string(), "", 0, 0, "the Ogg Theora encoder failed");
    }
  }

  void Finish() override {
    if (!started_) throw InputError(output_.path().string(), "", 0, 0, "a video needs frames");
    writer_->End();
    started_ = false;
    output_.Commit();
  }

 private:
  AtomicOutput output_;
  double fps_;
  vtkNew<vtkImageData> data_;
  vtkNew<vtkOggTheoraWriter> writer_;
  bool started_ = false;
  int width_ = 0, height_ = 0;
};

}  // namespace

std::unique_ptr<VideoWriter> MakeOggTheoraWriter(const std::filesystem::path& path, double fps,
                                                 const std::filesystem::path& protect) {
  return std::make_unique<OggTheoraWriter>(path, fps, protect);
}

}  // namespace mechanist
