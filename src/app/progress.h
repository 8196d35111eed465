// A one-line progress bar on stderr: redrawn in place on a terminal, every 10% otherwise.
#pragma once

#include <chrono>
#include <string>

namespace tidepool {

class Progress {
 public:
  Progress(std::string label, int total, bool enabled = true);
  void update(int done);
  void finish();

 private:
  std::string m_label;
  int m_total, m_lastDecile = -1;
  bool m_enabled, m_tty, m_finished = false;
  std::chrono::steady_clock::time_point m_start;
};

}  // namespace tidepool
