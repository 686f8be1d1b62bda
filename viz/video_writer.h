#pragma once

#include <filesystem>
#include <memory>

#include "viz/image.h"

namespace mechanist {

/// A video encoder fed one frame at a time. The file appears, atomically, only at Finish; a
/// writer destroyed before that leaves nothing behind.
class VideoWriter {
 public:
  virtual ~VideoWriter() = default;
  /// Appends a frame; every frame must have the size of the first.
  virtual void Add(const Image& frame) = 0;
  /// Ends the stream and moves the file into place. Throws InputError naming the file.
  virtual void Finish() = 0;
};

/// Ogg Theora (.ogv) through VTK's writer, `fps` frames per second. Throws InputError for a
/// path over `protect`.
std::unique_ptr<VideoWriter> MakeOggTheoraWriter(const std::filesystem::path& path, double fps,
                                                 const std::filesystem::path& protect = {});

/// True when the `ffmpeg` program is on the PATH.
bool FfmpegAvailable();

/// MP4 (H.264 with yuv420p, the most widely playable form; odd sizes padded by one pixel)
/// encoded by piping raw frames to the `ffmpeg` program. Throws InputError when ffmpeg is
/// missing, for a path over `protect`, or when ffmpeg fails (with its exit status).
std::unique_ptr<VideoWriter> MakeMp4Writer(const std::filesystem::path& path, double fps,
                                           const std::filesystem::path& protect = {});

}  // namespace mechanist
