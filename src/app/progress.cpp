#include "app/progress.h"

#include <unistd.h>

#include <cstdio>

namespace tidepool {

Progress::Progress(std::string label, int total, bool enabled)
    : m_label(std::move(label)),
      m_total(total),
      m_enabled(enabled),
      m_tty(isatty(STDERR_FILENO)),
      m_start(std::chrono::steady_clock::now()) {}

void Progress::update(int done) {
  if (!m_enabled || m_total <= 0) return;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
  const double rate = seconds > 0 ? done / seconds : 0;
  if (m_tty) {
    constexpr int kWidth = 30;
    const int filled = done * kWidth / m_total;
    std::fprintf(stderr, "\r%s [%.*s%*s] %d/%d  %.1f frames/s", m_label.c_str(), filled,
                 "##############################", kWidth - filled, "", done, m_total, rate);
    std::fflush(stderr);
  } else if (const int decile = done * 10 / m_total; decile != m_lastDecile) {
    m_lastDecile = decile;
    std::fprintf(stderr, "%s %3d%% (%d/%d, %.1f frames/s)\n", m_label.c_str(), int(100LL * done / m_total), done,
                 m_total, rate);  // a line per tenth, each with its own share: 33% at 1 of 3
  }
}

void Progress::finish() {
  if (m_enabled && m_tty && !m_finished) std::fprintf(stderr, "\n");
  m_finished = true;
}

}  // namespace tidepool
