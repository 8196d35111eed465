// The original apps' indicators, drawn over the image: frames and simulation steps per second
// (counters refreshed every 500 ms, as src/ts/ui/counter.ts), the particle count, the neighbour
// grid (cells per axis, cell edge) and, for 3D views, a small XYZ axes gizmo bottom right (away
// from the panel).
#pragma once

#include <cstdint>

#include "scene/stage.h"

namespace tidepool {

// Events per second over windows of `window` seconds: the shown value changes once a window.
// sample() takes a running total (frames, steps); a total that drops (the model was reset)
// counts from zero again, so a reset never shows a negative or huge rate.
class RateCounter {
 public:
  explicit RateCounter(double window = 0.5) : m_window(window) {}
  void sample(double nowSeconds, std::uint64_t total);
  double perSecond() const { return m_rate; }  // over the last full window; 0 before the first
  bool fresh() const { return m_fresh; }       // the last sample closed a window

 private:
  double m_window;
  bool m_started = false, m_fresh = false;
  double m_windowStart = 0;
  std::uint64_t m_last = 0;     // the total at the last sample
  std::uint64_t m_counted = 0;  // events since the first sample (across drops)
  std::uint64_t m_atStart = 0;  // m_counted when the window began
  double m_rate = 0;
};

// The counters the window keeps: one per displayed frame, one per simulation step.
struct Indicators {
  RateCounter frames, steps;
  std::uint64_t frameCount = 0;
  void update(double nowSeconds, const StageIndicators& s);  // once a displayed frame
};

void drawIndicators(const Indicators& counters, const StageIndicators& s);  // the overlay, top right
void drawAxesGizmo(const glm::mat4& view);  // X red, Y green, Z blue, bottom right, from the camera's view matrix

}  // namespace tidepool
