#include "io/checkpoint_diff.h"

#include <map>
#include <vector>

#include "io/json.h"

namespace tidepool::io {
namespace {

// "(219872 of 220000 bytes, the first at byte 0)"; "(8 bytes, not 16)" when the sizes differ.
std::string bytesApart(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  if (a.size() != b.size()) return "(" + std::to_string(a.size()) + " bytes, not " + std::to_string(b.size()) + ")";
  std::size_t differing = 0, first = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i] && differing++ == 0) first = i;
  return "(" + std::to_string(differing) + " of " + std::to_string(a.size()) + " bytes, the first at byte " +
         std::to_string(first) + ")";
}

}  // namespace

std::optional<std::string> checkpointDifference(const Checkpoint& a, const Checkpoint& b) {
  if (a.model != b.model) return "the models differ: " + printable(a.model) + " and " + printable(b.model);
  if (a.scene != b.scene) return "the scenes differ: " + printable(a.scene) + " and " + printable(b.scene);
  if (a.time != b.time)
    return "the times differ: " + std::to_string(a.time) + " s and " + std::to_string(b.time) + " s";
  if (a.steps != b.steps)
    return "the step counts differ: " + std::to_string(a.steps) + " and " + std::to_string(b.steps);
  std::vector<std::string> differing;
  if (a.params != b.params) differing.push_back("the parameters");
  std::map<std::string, const CheckpointEntry*> inB;
  for (const CheckpointEntry& e : b.entries) inB[e.name] = &e;
  for (const CheckpointEntry& e : a.entries) {
    const auto other = inB.find(e.name);
    if (other == inB.end())
      differing.push_back("'" + printable(e.name) + "' (only in the first)");
    else if (other->second->kind != e.kind || other->second->bytes != e.bytes)
      differing.push_back("'" + printable(e.name) + "' " + bytesApart(e.bytes, other->second->bytes));
    if (other != inB.end()) inB.erase(other);
  }
  for (const auto& [name, entry] : inB) differing.push_back("'" + printable(name) + "' (only in the second)");
  if (differing.empty()) return std::nullopt;
  std::string list;
  for (std::size_t i = 0; i < differing.size() && i < 4; ++i) list += (i ? ", " : "") + differing[i];
  if (differing.size() > 4) list += ", ...";
  const std::size_t entries = a.entries.size() + 1;  // the parameters count as one
  return std::to_string(differing.size()) + " of " + std::to_string(entries) + " entries differ: " + list;
}

}  // namespace tidepool::io
