// Raw RGBA frames piped to ffmpeg: H.264 (yuv420p) for .mp4 and the other names, or for .gif a
// looping GIF with one palette made for the clip (palettegen + paletteuse in one pass).
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <vector>

namespace tidepool::io {

bool ffmpegAvailable();                         // ffmpeg on PATH
bool isGif(const std::filesystem::path& path);  // ".gif", any case

class VideoWriter {
 public:
  // Throws Error when ffmpeg is not installed or cannot start.
  VideoWriter(const std::filesystem::path& path, int width, int height, int fps);
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  void write(const std::vector<std::uint8_t>& rgbaTopDown);
  void close();  // waits for ffmpeg; throws Error when it failed

 private:
  std::FILE* m_pipe = nullptr;
  std::filesystem::path m_path;
  std::size_t m_frameBytes = 0;
};

}  // namespace tidepool::io
