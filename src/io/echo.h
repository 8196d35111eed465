// How a path from the command line or a file is quoted in a one-line error: control bytes as
// \xNN, cut at 200 characters (a path is longer than a key or a value, and worth more of the line).
#pragma once

#include <filesystem>
#include <string>

#include "io/json.h"

namespace tidepool::io {

constexpr std::size_t kMaxPathEcho = 200;  // characters of a path quoted in an error

inline std::string shownPath(const std::filesystem::path& path) { return printable(path.string(), kMaxPathEcho); }

}  // namespace tidepool::io
