#include "base/progress.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace tidepool {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Steps* g_current = nullptr;  // the Steps alive now (commands run one at a time), for tick()

}  // namespace

std::string durationText(double seconds) {
  char text[48];
  if (!(seconds >= 0)) seconds = 0;
  if (seconds < 59.95) {
    std::snprintf(text, sizeof text, seconds < 9.95 ? "%.1f s" : "%.0f s", seconds);
  } else if (seconds < 3600) {
    const long s = std::lround(seconds);
    std::snprintf(text, sizeof text, "%ld min %ld s", s / 60, s % 60);
  } else {
    const long m = std::lround(seconds / 60);
    std::snprintf(text, sizeof text, "%ld h %ld min", m / 60, m % 60);
  }
  return text;
}

std::string groupedCount(std::uint64_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string estimateText(double lastSeconds, double elapsed, int done, int total, const std::string& unit) {
  const double all = elapsed + lastSeconds * double(total - done);
  const std::string one = unit.empty() ? unit : unit.substr(0, unit.size() - (unit.back() == 's' ? 1 : 0));
  return "first " + one + " " + durationText(lastSeconds) + ", about " + durationText(all) + " for " +
         std::to_string(total) + " " + (total == 1 ? one : unit);
}

Progress::Progress(std::string label, int total, bool enabled, std::string unit)
    : m_label(std::move(label)),
      m_unit(std::move(unit)),
      m_total(total),
      m_enabled(enabled),
      m_tty(isatty(STDERR_FILENO)),
      m_start(std::chrono::steady_clock::now()) {}

double Progress::seconds() const { return secondsSince(m_start); }

void Progress::update(int done) {
  if (!m_enabled || m_total <= 0) return;
  const double seconds = this->seconds();
  const double rate = seconds > 0 ? done / seconds : 0;
  if (m_tty) {
    constexpr int kWidth = 30;
    const int filled = done * kWidth / m_total;
    const std::string left =
        done > 0 && done < m_total ? ", " + durationText(seconds / done * (m_total - done)) + " left" : "";
    std::fprintf(stderr, "\r%s [%.*s%*s] %d/%d  %.1f %s/s%s   ", m_label.c_str(), filled,
                 "##############################", kWidth - filled, "", done, m_total, rate, m_unit.c_str(),
                 left.c_str());
    std::fflush(stderr);
    m_drawn = true;
  } else if (const int decile = done * 10 / m_total; decile != m_lastDecile) {
    m_lastDecile = decile;
    std::fprintf(stderr, "%s %3d%% (%d/%d, %.1f %s/s)\n", m_label.c_str(), int(100LL * done / m_total), done, m_total,
                 rate, m_unit.c_str());  // a line per tenth, each with its own share: 33% at 1 of 3
  }
}

void Progress::note(const std::string& line) {
  if (!m_enabled) return;
  std::fprintf(stderr, "%s%s\n", m_tty && m_drawn ? "\r\033[K" : "", line.c_str());
  std::fflush(stderr);
  m_drawn = false;
}

void Progress::finish() {
  if (m_enabled && m_tty && m_drawn && !m_finished) std::fprintf(stderr, "\n");
  m_finished = true;
}

Steps::Steps(std::string label, int total, std::string noun, bool enabled)
    : m_label(std::move(label)),
      m_noun(std::move(noun)),
      m_total(total),
      m_enabled(enabled),
      m_tty(isatty(STDERR_FILENO)),
      m_start(std::chrono::steady_clock::now()),
      m_stepStart(m_start),
      m_lastLine(m_start) {
  g_current = this;
}

Steps::~Steps() {
  if (g_current == this) g_current = nullptr;
  if (m_tty && m_drawn) std::fprintf(stderr, "\n");
}

void Steps::begin(const std::string& what) {
  ++m_begun;
  if (!m_enabled) return;
  const std::string sofar = m_begun > 1 ? " (" + durationText(secondsSince(m_start)) + " so far)" : "";
  std::fprintf(stderr, "%s%s %d/%d: %s%s\n", m_tty && m_drawn ? "\r\033[K" : "", m_label.c_str(), m_begun, m_total,
               what.c_str(), sofar.c_str());
  std::fflush(stderr);
  m_drawn = false;
  m_stepStart = m_lastLine = std::chrono::steady_clock::now();
}

void Steps::finish() {
  if (g_current == this) g_current = nullptr;
  if (!m_enabled || m_finished) return;
  m_finished = true;
  std::fprintf(stderr, "%s%s: %d %s in %s\n", m_tty && m_drawn ? "\r\033[K" : "", m_label.c_str(), m_begun,
               (m_noun + (m_begun == 1 ? "" : "s")).c_str(), durationText(secondsSince(m_start)).c_str());
  std::fflush(stderr);
  m_drawn = false;
}

void Steps::tick(int done, int total, const char* unit) {
  if (g_current) g_current->inside(done, total, unit);
}

void Steps::note(const std::string& what) {
  Steps* s = g_current;
  if (!s || !s->m_enabled) return;
  std::fprintf(stderr, "%s%s: %s (%s so far)\n", s->m_tty && s->m_drawn ? "\r\033[K" : "", s->m_label.c_str(),
               what.c_str(), durationText(secondsSince(s->m_start)).c_str());
  std::fflush(stderr);
  s->m_drawn = false;
  s->m_lastLine = std::chrono::steady_clock::now();
}

void Steps::inside(int done, int total, const char* unit) {
  if (!m_enabled || total <= 0 || m_begun == 0) return;
  const double inStep = secondsSince(m_stepStart);
  const std::string left =
      done > 0 && done < total ? ", about " + durationText(inStep / done * (total - done)) + " left" : "";
  if (m_tty && (secondsSince(m_lastLine) >= 0.1 || done == total)) {  // redrawn at most ten times a second
    m_lastLine = std::chrono::steady_clock::now();
    std::fprintf(stderr, "\r  %d/%d %s, %s%s\033[K", done, total, unit, durationText(inStep).c_str(), left.c_str());
    std::fflush(stderr);
    m_drawn = true;
  } else if (!m_tty && secondsSince(m_lastLine) >= kQuietSeconds && done < total) {
    std::fprintf(stderr, "  %d/%d %s, %s%s\n", done, total, unit, durationText(inStep).c_str(), left.c_str());
    m_lastLine = std::chrono::steady_clock::now();
  }
}

}  // namespace tidepool
