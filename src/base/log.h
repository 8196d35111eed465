// Minimal logging to stderr. The window app also keeps recent lines to show in its log panel.
#pragma once

#include <functional>
#include <string>

namespace tidepool::log {

enum class Level { Debug, Info, Warn, Error };

void setLevel(Level level);  // messages below it are dropped (default Info)
void write(Level level, const std::string& message);
using Sink = std::function<void(Level, const std::string&)>;
void setSink(Sink sink);  // extra receiver (e.g. the UI log panel); nullptr removes it

inline void debug(const std::string& m) { write(Level::Debug, m); }
inline void info(const std::string& m) { write(Level::Info, m); }
inline void warn(const std::string& m) { write(Level::Warn, m); }
inline void error(const std::string& m) { write(Level::Error, m); }

}  // namespace tidepool::log
