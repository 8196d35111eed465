#include "base/log.h"

#include <cstdio>
#include <mutex>

namespace tidepool::log {
namespace {
std::mutex g_mutex;
Level g_level = Level::Info;
Sink g_sink;
const char* prefix(Level l) {
  switch (l) {
    case Level::Debug: return "debug: ";
    case Level::Info: return "";
    case Level::Warn: return "warning: ";
    case Level::Error: return "error: ";
  }
  return "";
}
}  // namespace

void setLevel(Level level) {
  std::lock_guard lock(g_mutex);
  g_level = level;
}
void setSink(Sink sink) {
  std::lock_guard lock(g_mutex);
  g_sink = std::move(sink);
}

void write(Level level, const std::string& message) {
  std::lock_guard lock(g_mutex);
  if (g_sink) g_sink(level, message);
  if (level < g_level) return;
  std::fprintf(stderr, "%s%s\n", prefix(level), message.c_str());
}

}  // namespace tidepool::log
