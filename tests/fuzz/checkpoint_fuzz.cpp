// Checkpoint files (io/checkpoint_file.cpp). The first byte picks what the rest is: odd, the
// whole file as read from disk; even, the payload alone, which this target seals with a valid
// header (magic, version, its CRC-32 and size) so that mutations reach the field reader behind
// the checksum. A checkpoint that parses must encode to bytes that parse to the same fields.
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "fuzz/fuzz_check.h"
#include "io/checkpoint_file.h"

namespace {

void put(std::vector<std::uint8_t>& out, std::uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(std::uint8_t(v >> (8 * i)));
}

std::vector<std::uint8_t> sealed(std::span<const std::uint8_t> payload) {
  using namespace tidepool::io;
  std::vector<std::uint8_t> file(kCheckpointMagic, kCheckpointMagic + 8);
  put(file, kCheckpointVersion, 4);
  put(file, crc32(payload), 4);
  put(file, payload.size(), 8);
  file.insert(file.end(), payload.begin(), payload.end());
  return file;
}

bool same(const tidepool::io::Checkpoint& a, const tidepool::io::Checkpoint& b) {
  if (a.model != b.model || a.scene != b.scene || a.params != b.params || a.steps != b.steps ||
      std::memcmp(&a.time, &b.time, sizeof a.time) != 0 || a.entries.size() != b.entries.size())
    return false;
  for (std::size_t i = 0; i < a.entries.size(); ++i)
    if (a.entries[i].kind != b.entries[i].kind || a.entries[i].name != b.entries[i].name ||
        a.entries[i].bytes != b.entries[i].bytes)
      return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tidepool;
  if (size == 0) return 0;
  const std::span<const std::uint8_t> rest(data + 1, size - 1);
  const std::vector<std::uint8_t> file =
      data[0] & 1 ? std::vector<std::uint8_t>(rest.begin(), rest.end()) : sealed(rest);
  fuzz::expectParsedOrRefused("fuzz.ckpt", [&] {
    const io::Checkpoint c = io::parseCheckpoint(file, "fuzz.ckpt");
    if (!same(io::parseCheckpoint(io::encodeCheckpoint(c), "again.ckpt"), c))
      fuzz::finding("checkpoint changed through encode -> parse");
  });
  return 0;
}
