#include <fmt/format.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "io/atomic_file.h"
#include "io/input_error.h"
#include "viz/video_writer.h"

namespace mechanist {
namespace {

// Single-quoted for /bin/sh.
std::string Quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

class Mp4Writer final : public VideoWriter {
 public:
  Mp4Writer(const std::filesystem::path& path, double fps, const std::filesystem::path& protect)
      : output_(path, protect), fps_(fps) {
    if (!FfmpegAvailable()) {
      throw InputError(path.string(), "", 0, 0,
                       "MP4 needs the ffmpeg program (Debian package ffmpeg), not found on PATH");
    }
  }

  ~Mp4Writer() override {
    if (pipe_) ::pclose(pipe_);
  }

  void Add(const Image& frame) override {
    if (!pipe_) {
      width_ = frame.width;
      height_ = frame.height;
      const std::string command = fmt::format(
          "ffmpeg -loglevel error -y -f rawvideo -pix_fmt rgb24 -s {}x{} -framerate {} -i - -vf "
          "'pad=ceil(iw/2)*2:ceil(ih/2)*2' -c:v libx264 -pix_fmt yuv420p -movflags +faststart -f "
          "mp4 {}",
          width_, height_, std::to_string(fps_), Quoted(output_.temporary().string()));
      pipe_ = ::popen(command.c_str(), "w");
      if (!pipe_) throw InputError(output_.path().string(), "", 0, 0, "cannot start ffmpeg");
    }
    if (frame.width != width_ || frame.height != height_) {
      throw InputError(output_.path().string(), "", 0, 0, "video frames differ in size");
    }
    if (std::fwrite(frame.rgb.data(), 1, frame.rgb.size(), pipe_) != frame.rgb.size()) {
      throw InputError(output_.path().string(), "", 0, 0, "ffmpeg stopped reading frames");
    }
  }

  void Finish() override {
    if (!pipe_) throw InputError(output_.path().string(), "", 0, 0, "a video needs frames");
    const int status = ::pclose(pipe_);
    pipe_ = nullptr;
    if (status != 0) {
      throw InputError(output_.path().string(), "", 0, 0,
                       fmt::format("ffmpeg failed (exit status {})",
                                   WIFEXITED(status) ? WEXITSTATUS(status) : status));
    }
    output_.Commit();
  }

 private:
  AtomicOutput output_;
  double fps_;
  std::FILE* pipe_ = nullptr;
  int width_ = 0, height_ = 0;
};

}  // namespace

bool FfmpegAvailable() { return std::system("command -v ffmpeg > /dev/null 2>&1") == 0; }

std::unique_ptr<VideoWriter> MakeMp4Writer(const std::filesystem::path& path, double fps,
                                           const std::filesystem::path& protect) {
  return std::make_unique<Mp4Writer>(path, fps, protect);
}

}  // namespace mechanist
