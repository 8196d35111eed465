#include "io/json.h"

#include <fstream>
#include <sstream>

#include "base/error.h"

namespace tidepool::io {

std::string readTextFile(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw Error("file not found: '" + path.string() + "'");
  if (std::filesystem::is_directory(path, ec)) throw Error("'" + path.string() + "' is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot read '" + path.string() + "': permission denied or unreadable");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

Json parseJson(const std::string& text, const std::string& name) {
  try {
    return Json::parse(text);
  } catch (const Json::parse_error& e) {
    // Line and column of the byte where parsing stopped (1-based).
    const std::size_t end = std::min<std::size_t>(e.byte == 0 ? 0 : e.byte - 1, text.size());
    int line = 1, column = 1;
    for (std::size_t i = 0; i < end; ++i) {
      if (text[i] == '\n') {
        ++line;
        column = 1;
      } else
        ++column;
    }
    std::string what = e.what();
    const std::size_t colon = what.find(": ", what.find("parse error"));
    if (colon != std::string::npos) what = what.substr(colon + 2);
    throw Error(name + ":" + std::to_string(line) + ":" + std::to_string(column) + ": malformed JSON: " + what);
  }
}

Json readJsonFile(const std::filesystem::path& path) { return parseJson(readTextFile(path), path.string()); }

void writeJsonFile(const std::filesystem::path& path, const Json& json) {
  std::ofstream out(path);
  if (!out) throw Error("cannot write '" + path.string() + "'");
  out << json.dump(2) << "\n";
}

}  // namespace tidepool::io
