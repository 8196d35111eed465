#include "io/video.h"

#include <unistd.h>
#include <cctype>
#include <csignal>
#include <cstdlib>
#include <sstream>
#include <string>

#include "base/error.h"
#include "io/echo.h"

namespace tidepool::io {

bool ffmpegAvailable() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':'))
    if (!dir.empty() && access((dir + "/ffmpeg").c_str(), X_OK) == 0) return true;
  return false;
}

namespace {
// The path as one shell word: in single quotes, each quote in it written as '\''.
std::string shellQuoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}
}  // namespace

bool isGif(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".gif";
}

VideoWriter::VideoWriter(const std::filesystem::path& path, int width, int height, int fps)
    : m_path(path), m_frameBytes(std::size_t(width) * height * 4) {
  if (!ffmpegAvailable())
    throw Error("--video needs ffmpeg, which is not installed (apt-get install ffmpeg); PNG frames need no ffmpeg");
  std::signal(SIGPIPE, SIG_IGN);  // a dying ffmpeg must give a write error, not kill us
  std::ostringstream cmd;
  cmd << "ffmpeg -loglevel error -y -f rawvideo -pix_fmt rgba -s " << width << "x" << height << " -r " << fps
      << " -i - ";
  if (isGif(path))  // one palette of 256 colours made for this clip, dithered: far cleaner than the web palette
    cmd << "-filter_complex '[0:v]split[a][b];[a]palettegen=stats_mode=full[p];[b][p]paletteuse=dither=sierra2_4a' "
        << "-loop 0 ";
  else  // H.264 in yuv420p needs even sizes: pad by one pixel where needed
    cmd << "-vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -pix_fmt yuv420p -c:v libx264 -crf 18 ";
  // Absolute, so the name starts with '/': ffmpeg never reads "-version" or "-" as an option or stdout.
  cmd << shellQuoted(std::filesystem::absolute(path).string());
  m_pipe = popen(cmd.str().c_str(), "w");
  if (!m_pipe) throw Error("cannot start ffmpeg to write '" + shownPath(path) + "'");
}

VideoWriter::~VideoWriter() {
  if (m_pipe) pclose(m_pipe);
}

void VideoWriter::write(const std::vector<std::uint8_t>& rgba) {
  if (!m_pipe || rgba.size() != m_frameBytes) throw Error("video frame has the wrong size");
  if (std::fwrite(rgba.data(), 1, rgba.size(), m_pipe) != rgba.size())
    throw Error("ffmpeg stopped accepting frames for '" + shownPath(m_path) + "'");
}

void VideoWriter::close() {
  if (!m_pipe) return;
  const int status = pclose(m_pipe);
  m_pipe = nullptr;
  if (status != 0) throw Error("ffmpeg failed writing '" + shownPath(m_path) + "' (see its message above)");
  // ffmpeg can end well having written nothing: only a file that is there and holds bytes was written.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(m_path, ec) || std::filesystem::file_size(m_path, ec) == 0 || ec)
    throw Error("ffmpeg ended without writing '" + shownPath(m_path) + "' (see its message above)");
}

}  // namespace tidepool::io
