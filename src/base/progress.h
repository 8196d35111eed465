// Progress of long runs, on stderr so that stdout (tables, CSV) stays clean. On a terminal a line
// is redrawn in place; otherwise (logs, pipes, tests) Progress writes a line per tenth of the work
// and Steps a line per step, with a heartbeat at most every kQuietSeconds inside a long step.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace tidepool {

std::string durationText(double seconds);   // 0.42 -> "0.4 s", 285 -> "4 min 45 s", 35530 -> "9 h 52 min"
std::string groupedCount(std::uint64_t n);  // 262144 -> "262,144"
// The estimate after the first measured frame, `lastSeconds` long, with `done` of `total` frames
// finished in `elapsed` seconds: "first frame 1.9 s, about 4 min 45 s for 150 frames" (the rest at
// that frame's pace).
std::string estimateText(double lastSeconds, double elapsed, int done, int total, const std::string& unit);

// A bar over `total` units of work (frames): "rendering cup [#####     ] 25/150  1.2 frames/s".
class Progress {
 public:
  Progress(std::string label, int total, bool enabled = true, std::string unit = "frames");
  void update(int done);               // `done` units finished
  void note(const std::string& line);  // a line of its own, the bar redrawn under it on a terminal
  void finish();
  double seconds() const;  // since construction

 private:
  std::string m_label, m_unit;
  int m_total, m_lastDecile = -1;
  bool m_enabled, m_tty, m_finished = false, m_drawn = false;
  std::chrono::steady_clock::time_point m_start;
};

// The steps of a long command (a benchmark's rows, a study's runs, validate's checks), announced
// as each starts: "bench balls 2/4: 1048576 balls, determ. off (12.4 s so far)". While a Steps is
// alive, tick() (called from the loops that time or run work) reports progress inside the step.
class Steps {
 public:
  static constexpr double kQuietSeconds = 30;  // off a terminal: a heartbeat line at most this often

  Steps(std::string label, int total, std::string noun = "row", bool enabled = true);
  ~Steps();
  Steps(const Steps&) = delete;
  Steps& operator=(const Steps&) = delete;
  void begin(const std::string& what);                      // step k+1 of total starts
  void finish();                                            // "bench balls: 4 rows in 1 min 3 s" (noun "row"), once
  static void tick(int done, int total, const char* unit);  // inside the current step; no-op without one
  // A line for a piece of work that finished (a study's row), where steps are not known ahead:
  // "sweep water-density: balls, dt 0.002: 1.2 ms per simulated s (40 s so far)". No-op without one.
  static void note(const std::string& what);

 private:
  void inside(int done, int total, const char* unit);
  std::string m_label, m_noun;
  int m_total, m_begun = 0;
  bool m_enabled, m_tty, m_finished = false, m_drawn = false;
  std::chrono::steady_clock::time_point m_start, m_stepStart, m_lastLine;
};

}  // namespace tidepool
