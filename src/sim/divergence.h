// Watching a simulation for divergence without stalling the GPU. A model reduces its state to a
// few numbers on the GPU every few frames (NaN count, largest magnitudes) and hands them here
// through an AsyncReadback; when they arrive one to two frames later they are judged. Healthy
// results promote the state copied at that same moment to "last good state", so a blow-up can
// be undone exactly.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "gl/async_readback.h"

namespace tidepool {

struct Health {
  double time = 0;          // simulated seconds at the check
  double nanCount = 0;      // non-finite values in the state
  double maxMagnitude = 0;  // largest |value| of the watched quantity
};

struct DivergenceReport {
  std::string message;  // what failed, with method and time step, and what to do
  double time = 0;      // simulated seconds of the failed check
};

// A float the health reduction stored as its bits in one word (e.g. the largest speed).
float healthFloat(std::uint32_t word);

// The report of a failed check, worded alike for every model:
//   "<model> diverged by t = <time> s: <what> (<method>); halve the time step and resume from the
//   last good state" (or "... and reset" when no good state was kept).
DivergenceReport divergenceReport(const std::string& model, double time, const std::string& what,
                                  const std::string& method, bool hasGood);

// The watch's timing, shared by the models: a check every `interval` frames, never two in flight,
// none while `allowed` is false (after a divergence, with nothing to watch). A model's check
// reduces its state into a health buffer whose first four 32-bit words come back here.
class CheckCycle {
 public:
  using Words = std::array<std::uint32_t, 4>;
  using Judge = std::function<void(const Words& words, double time)>;  // time: of the state checked

  explicit CheckCycle(int interval) : m_interval(interval) {}
  // Once per frame: a finished check goes to judge(); then, when one is due, start() runs the
  // model's reduction into `health` (and copies the state it judges) and the read-back begins.
  void frame(double time, bool allowed, const Judge& judge, const std::function<void()>& start,
             const gl::Buffer& health);
  void flush(const Judge& judge);  // waits for the check in flight and judges it
  void restart();                  // drops the check in flight (reset, recovery); counts from 0

 private:
  gl::AsyncReadback m_readback;
  double m_time = 0;  // of the state the check in flight judges
  int m_interval;
  int m_frames = 0;
};

}  // namespace tidepool
