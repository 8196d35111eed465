// JSON files with errors a person can act on: "scene.json:3:14: malformed JSON: ...".
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace tidepool::io {

using Json = nlohmann::json;

Json readJsonFile(const std::filesystem::path& path);              // throws Error (missing, unreadable, malformed)
Json parseJson(const std::string& text, const std::string& name);  // name is used in messages
void writeJsonFile(const std::filesystem::path& path, const Json& json);
std::string readTextFile(const std::filesystem::path& path);  // throws Error naming the path

}  // namespace tidepool::io
