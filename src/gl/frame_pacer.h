// Frame pacing with fences (GL 3.2 sync objects): the CPU never queues more than maxInFlight
// frames ahead of the GPU, so a slow step makes the loop wait here (where input was just read)
// instead of in a driver queue several frames deep, and the window keeps answering.
//
//   FramePacer pacer(2);
//   for (;;) { pacer.waitForSlot(); poll(); step(); render(); swap(); pacer.frameSubmitted(); }
//
// A ring of fences, one per frame in flight: frameSubmitted() fences the frame's commands and
// flushes them; waitForSlot() retires the signalled fences and, while maxInFlight are still
// pending, waits on the oldest.
#pragma once

#include <cstdint>
#include <deque>

#include "gl/gl.h"

namespace tidepool::gl {

class FramePacer {
 public:
  explicit FramePacer(int maxInFlight = 2);  // clamped to 1..8
  ~FramePacer();
  FramePacer(const FramePacer&) = delete;
  FramePacer& operator=(const FramePacer&) = delete;

  void waitForSlot();     // before a frame: returns when fewer than maxInFlight frames are pending
  void frameSubmitted();  // after a frame's last command (the swap): fences it
  int inFlight() const { return int(m_fences.size()); }  // frames fenced and not seen done
  int maxInFlight() const { return m_max; }
  std::uint64_t waits() const { return m_waits; }  // frames that had to wait (the GPU was behind)

 private:
  void retireSignalled();  // drops the fences already signalled, oldest first

  int m_max;
  std::deque<GLsync> m_fences;  // oldest first
  std::uint64_t m_waits = 0;
};

}  // namespace tidepool::gl
