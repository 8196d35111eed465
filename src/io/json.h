// JSON files with errors a person can act on: "scene.json:3:14: malformed JSON: ...".
// Files larger than kMaxJsonFileBytes and values nested deeper than kMaxJsonDepth (io/limits.h)
// are refused before parsing, naming the file and (for the depth) the line and column.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "io/limits.h"

namespace tidepool::io {

using Json = nlohmann::json;

Json readJsonFile(const std::filesystem::path& path);              // throws Error (missing, unreadable, malformed)
Json parseJson(const std::string& text, const std::string& name);  // name is used in messages
void writeJsonFile(const std::filesystem::path& path, const Json& json);
std::string readTextFile(const std::filesystem::path& path);  // throws Error naming the path (kMaxTextFileBytes)
// A whole regular file of at most maxBytes (`kind` names it in the error: "a JSON file"); refuses
// directories, devices and pipes (/dev/zero never ends). Throws Error naming the path.
std::string readFileLimited(const std::filesystem::path& path, std::uintmax_t maxBytes, const char* kind);

// Input quoted in a one-line error: a JSON value as JSON, text with control bytes as \xNN, each
// cut to `max` characters ("[1,2,3,4,..."), so a hostile file cannot make the message long or
// break it over lines.
std::string excerpt(const Json& value, std::size_t max = 60);
std::string printable(std::string_view text, std::size_t max = 60);

}  // namespace tidepool::io
