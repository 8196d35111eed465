#include "app/frame_writer.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <string_view>

#include "io/echo.h"

namespace tidepool {
namespace {

// The number of "frame_<digits>.png" (as frameFileName writes it, or with more digits); nullopt
// for any other name.
std::optional<std::uint64_t> frameNumber(const std::string& name) {
  constexpr std::string_view prefix = "frame_", suffix = ".png";
  if (name.size() < prefix.size() + 5 + suffix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
    return std::nullopt;
  const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
  if (digits.size() > 18 || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::nullopt;
  return std::stoull(digits);
}

}  // namespace

std::string frameFileName(std::uint64_t frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05llu.png", static_cast<unsigned long long>(frame));
  return name;
}

std::string staleFramesWarning(const std::filesystem::path& dir, std::uint64_t last) {
  std::size_t count = 0;
  std::uint64_t lowest = std::numeric_limits<std::uint64_t>::max(), highest = 0;
  std::error_code ec;
  for (auto it = std::filesystem::directory_iterator(dir, ec); !ec && it != std::filesystem::directory_iterator();
       it.increment(ec)) {
    const std::optional<std::uint64_t> n = frameNumber(it->path().filename().string());
    if (!n || *n <= last) continue;
    ++count;
    lowest = std::min(lowest, *n);
    highest = std::max(highest, *n);
  }
  if (count == 0) return "";
  return io::shownPath(dir) + " holds " + std::to_string(count) + " older frame" + (count == 1 ? "" : "s") +
         " beyond " + frameFileName(last) + " (" + frameFileName(lowest) +
         (count == 1 ? "" : " to " + frameFileName(highest)) + ") from an earlier run; delete them or use a new --out";
}

FrameWriter::~FrameWriter() {
  for (auto& f : m_pending)
    if (f.valid()) f.wait();
}

void FrameWriter::write(std::filesystem::path path, io::Image image) {
  while (m_pending.size() >= m_maxInFlight) {
    m_pending.front().get();
    m_pending.pop_front();
  }
  m_pending.push_back(
      std::async(std::launch::async, [p = std::move(path), img = std::move(image)] { io::writePng(p, img); }));
}

void FrameWriter::finish() {
  while (!m_pending.empty()) {
    auto f = std::move(m_pending.front());
    m_pending.pop_front();
    f.get();
  }
}

}  // namespace tidepool
