// Hostile checkpoints for tests: one entry (or the parameters) changed and the file sealed again,
// its header's size and CRC-32 recomputed as anyone can, so that only the checks behind the
// checksum stand between the file and the model.
//
//   test::editCheckpointFile(good, bad, [](io::Checkpoint& c) { test::setValue(c, "model.rain_debt", INFINITY); });
#pragma once

#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "base/error.h"
#include "io/checkpoint_file.h"

namespace tidepool::test {

inline io::CheckpointEntry& entryOf(io::Checkpoint& c, const std::string& name) {
  for (io::CheckpointEntry& e : c.entries)
    if (e.name == name) return e;
  throw Error("the checkpoint has no entry '" + name + "'");
}

// The entry's bytes become those of `v` (a value of the width the model saves).
template <class T>
void setValue(io::Checkpoint& c, const std::string& name, const T& v) {
  io::CheckpointEntry& e = entryOf(c, name);
  e.bytes.resize(sizeof v);
  std::memcpy(e.bytes.data(), &v, sizeof v);
}

// Element `index` of a buffer entry of T (a glm::vec4 of positions, a float of a heightfield).
template <class T>
void setElement(io::Checkpoint& c, const std::string& name, std::size_t index, const T& v) {
  io::CheckpointEntry& e = entryOf(c, name);
  if ((index + 1) * sizeof v > e.bytes.size()) throw Error("entry '" + name + "' is too small");
  std::memcpy(e.bytes.data() + index * sizeof v, &v, sizeof v);
}

// `from` read, edited and written to `to`, sealed (valid header and checksum).
inline void editCheckpointFile(const std::filesystem::path& from, const std::filesystem::path& to,
                               const std::function<void(io::Checkpoint&)>& edit) {
  io::Checkpoint c = io::readCheckpointFile(from);
  edit(c);
  const std::vector<std::uint8_t> bytes = io::encodeCheckpoint(c);
  std::ofstream out(to, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

}  // namespace tidepool::test
