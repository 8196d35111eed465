// Writes PNG frames on background threads so encoding overlaps the next frame's GPU work.
#pragma once

#include <cstdint>
#include <deque>
#include <filesystem>
#include <future>
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

}  // namespace tidepool
