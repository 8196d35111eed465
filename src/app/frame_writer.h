// Writes PNG frames on background threads so encoding overlaps the next frame's GPU work.
#pragma once

#include <cstdint>
#include <deque>
#include <filesystem>
#include <future>
#include <optional>
#include <string>
#include <vector>

#include "io/png.h"

namespace tidepool {

class FrameWriter {
 public:
  explicit FrameWriter(std::size_t maxInFlight = 4) : m_maxInFlight(maxInFlight) {}
  ~FrameWriter();
  void write(std::filesystem::path path, io::Image image);  // blocks while too many are in flight
  void finish();                                            // waits; rethrows the first error

 private:
  std::size_t m_maxInFlight;
  std::deque<std::future<void>> m_pending;
};

// "frame_00042.png": a clip's frame `frame` in its --out folder (five digits at least).
std::string frameFileName(std::uint64_t frame);

// The warning when `dir` holds PNG frames numbered after `last`, the last one this run wrote (left
// by an earlier, longer run: a clip read back as frame_*.png would mix them in); "" when none.
// Frames before this run's first are a resumed run's predecessors and not counted. Deletes nothing.
//   warning text: "out/cup holds 117 older frames beyond frame_00002.png (frame_00003.png to
//   frame_00119.png) from an earlier run; delete them or use a new --out"
std::string staleFramesWarning(const std::filesystem::path& dir, std::uint64_t last);

}  // namespace tidepool
