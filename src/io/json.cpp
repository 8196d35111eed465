#include "io/json.h"

#include <fstream>
#include <sstream>
#include <unordered_set>
#include <vector>

#include "base/error.h"
#include "io/echo.h"

namespace tidepool::io {
namespace {

// 1-based line and column of byte `offset` of `text`.
std::string lineColumn(const std::string& text, std::size_t offset) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i < std::min(offset, text.size()); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else
      ++column;
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

// nlohmann's parser keeps its own stack, but copying, comparing and dumping a value recurse once
// per level: refuse deep nesting before parsing, at the bracket that goes too deep.
void checkDepth(const std::string& text, const std::string& name) {
  int depth = 0;
  bool inString = false, escaped = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth)
        throw Error(name + ":" + lineColumn(text, i) + ": JSON nested deeper than " + std::to_string(kMaxJsonDepth) +
                    " levels");
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

// Where the quoted key that ends just before byte `end` begins (its opening quote).
std::size_t keyStart(const std::string& text, std::size_t end) {
  for (std::size_t from = end >= 2 ? end - 2 : 0;;) {
    const std::size_t quote = text.rfind('"', from);
    if (quote == std::string::npos) return 0;
    std::size_t slashes = 0;
    while (quote > slashes && text[quote - 1 - slashes] == '\\') ++slashes;
    if (slashes % 2 == 0 || quote == 0) return quote;
    from = quote - 1;
  }
}

}  // namespace

std::string printable(std::string_view text, std::size_t max) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (out.size() >= max) return out + "...";
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7f) {
      static const char hex[] = "0123456789abcdef";
      out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
    } else {
      out += char(c);
    }
  }
  return out;
}

std::string excerpt(const Json& value, std::size_t max) {
  // Strings were valid UTF-8 when parsed; replace keeps a value built in code from throwing here.
  return printable(value.dump(-1, ' ', false, Json::error_handler_t::replace), max);
}

std::string byteSize(std::uintmax_t bytes) {
  if (bytes < kMiB) return std::to_string(bytes) + " bytes";
  std::ostringstream o;
  o.precision(bytes % kMiB == 0 ? 0 : 1);
  o << std::fixed << double(bytes) / double(kMiB) << " MiB";
  return o.str();
}

std::string readFileLimited(const std::filesystem::path& path, std::uintmax_t maxBytes, const char* kind) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) throw Error("file not found: '" + shownPath(path) + "'");
  if (fs::is_directory(status)) throw Error("'" + shownPath(path) + "' is a directory, not a file");
  if (!fs::is_regular_file(status))
    throw Error("'" + shownPath(path) + "' is not a regular file (a device, pipe or socket): give " + kind);
  const std::uintmax_t size = fs::file_size(path, ec);
  const auto tooLarge = [&](const std::string& size) {
    return Error("'" + shownPath(path) + "' is " + size + ", larger than the " + byteSize(maxBytes) + " allowed for " +
                 kind);
  };
  if (!ec && size > maxBytes) throw tooLarge(byteSize(size));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot read '" + shownPath(path) + "': permission denied or unreadable");
  // Reads in pieces, stopping one piece past the limit: a file that grows while it is read (or
  // whose size was unknown) is still refused.
  std::string text;
  if (!ec) text.reserve(std::size_t(size));
  std::vector<char> piece(64 * 1024);
  while (in) {
    in.read(piece.data(), std::streamsize(piece.size()));
    text.append(piece.data(), std::size_t(in.gcount()));
    if (text.size() > maxBytes) throw tooLarge("more than that");
  }
  if (in.bad()) throw Error("cannot read '" + shownPath(path) + "': read error");
  return text;
}

std::string readTextFile(const std::filesystem::path& path) {
  return readFileLimited(path, kMaxTextFileBytes, "a text file");
}

Json parseJson(const std::string& text, const std::string& name) {
  if (text.size() > kMaxJsonFileBytes)
    throw Error(name + ": " + byteSize(text.size()) + " of JSON, larger than the " + byteSize(kMaxJsonFileBytes) +
                " allowed");
  checkDepth(text, name);
  // A key given twice in one object would silently take its last value: refused where the second
  // one is. The callback sees no position, the stream does: its read position is just past the key.
  std::istringstream in(text);
  std::vector<std::unordered_set<std::string>> keys;  // of each object open around the parser
  const auto unique = [&](int, Json::parse_event_t event, Json& parsed) {
    if (event == Json::parse_event_t::object_start) keys.emplace_back();
    if (event == Json::parse_event_t::object_end) keys.pop_back();
    if (event == Json::parse_event_t::key) {
      const std::string& key = parsed.get_ref<const std::string&>();
      if (!keys.back().insert(key).second) {
        const auto end = std::size_t(in.rdbuf()->pubseekoff(0, std::ios::cur, std::ios::in));
        throw Error(name + ":" + lineColumn(text, keyStart(text, end)) + ": key \"" + printable(key) +
                    "\" given twice in one object");
      }
    }
    return true;
  };
  try {
    return Json::parse(in, unique);
  } catch (const Json::parse_error& e) {
    // Line and column of the byte where parsing stopped (1-based).
    const std::size_t end = std::min<std::size_t>(e.byte == 0 ? 0 : e.byte - 1, text.size());
    std::string what = e.what();
    const std::size_t colon = what.find(": ", what.find("parse error"));
    if (colon != std::string::npos) what = what.substr(colon + 2);
    throw Error(name + ":" + lineColumn(text, end) + ": malformed JSON: " + printable(what, 200));
  } catch (const Json::exception& e) {
    // A number too large for a double ("number overflow parsing '1e999'") has no byte offset:
    // the place is where its text first appears.
    std::string what = e.what();
    what = what.substr(what.find(']') + std::min<std::size_t>(2, what.size() - what.find(']')));
    std::size_t at = std::string::npos;
    if (const std::size_t q = what.find('\''); q != std::string::npos)
      at = text.find(what.substr(q + 1, what.find('\'', q + 1) - q - 1));
    throw Error(name + (at == std::string::npos ? "" : ":" + lineColumn(text, at)) +
                ": malformed JSON: " + printable(what, 200));
  }
}

Json readJsonFile(const std::filesystem::path& path) {
  return parseJson(readFileLimited(path, kMaxJsonFileBytes, "a JSON file"), shownPath(path));
}

void writeJsonFile(const std::filesystem::path& path, const Json& json) {
  std::ofstream out(path);
  if (!out) throw Error("cannot write '" + shownPath(path) + "'");
  out << json.dump(2) << "\n";
}

}  // namespace tidepool::io
