#include "io/video.h"

#include <unistd.h>
#include <csignal>
#include <cstdlib>
#include <sstream>
#include <string>

#include "base/error.h"

namespace tidepool::io {

bool ffmpegAvailable() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':'))
    if (!dir.empty() && access((dir + "/ffmpeg").c_str(), X_OK) == 0) return true;
  return false;
}

VideoWriter::VideoWriter(const std::filesystem::path& path, int width, int height, int fps)
    : m_path(path), m_frameBytes(std::size_t(width) * height * 4) {
  if (!ffmpegAvailable())
    throw Error("--video needs ffmpeg, which is not installed (apt-get install ffmpeg); PNG frames need no ffmpeg");
  std::signal(SIGPIPE, SIG_IGN);  // a dying ffmpeg must give a write error, not kill us
  // yuv420p needs even sizes: pad by one pixel where needed.
  std::ostringstream cmd;
  cmd << "ffmpeg -loglevel error -y -f rawvideo -pix_fmt rgba -s " << width << "x" << height << " -r " << fps
      << " -i - -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -pix_fmt yuv420p -c:v libx264 -crf 18 '" << path.string() << "'";
  m_pipe = popen(cmd.str().c_str(), "w");
  if (!m_pipe) throw Error("cannot start ffmpeg to write '" + path.string() + "'");
}

VideoWriter::~VideoWriter() {
  if (m_pipe) pclose(m_pipe);
}

void VideoWriter::write(const std::vector<std::uint8_t>& rgba) {
  if (!m_pipe || rgba.size() != m_frameBytes) throw Error("video frame has the wrong size");
  if (std::fwrite(rgba.data(), 1, rgba.size(), m_pipe) != rgba.size())
    throw Error("ffmpeg stopped accepting frames for '" + m_path.string() + "'");
}

void VideoWriter::close() {
  if (!m_pipe) return;
  const int status = pclose(m_pipe);
  m_pipe = nullptr;
  if (status != 0) throw Error("ffmpeg failed writing '" + m_path.string() + "' (see its message above)");
}

}  // namespace tidepool::io
