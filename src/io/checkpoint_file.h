// Checkpoint files: the full state of a running scene in one versioned binary file (no GL here:
// scene/checkpoint.h fills and applies it). Little-endian throughout; the layout (format 1):
//
//   offset  bytes  field
//   0       8      magic "TIDEPOOL"
//   8       4      u32 format version (kCheckpointVersion)
//   12      4      u32 CRC-32 (IEEE, as zlib's crc32) of the payload
//   16      8      u64 payload bytes (the file is exactly 24 + this long)
//   24      ...    payload:
//                    str model        the scene's model ("balls", "fluid", ...), at most 64 bytes
//                    str scene        the scene file it ran, at most 4096 bytes (for messages)
//                    str params       the stage's parameters as they were, JSON text, at most 16 MiB
//                    f64 time         simulated seconds
//                    u64 steps        steps taken (where the model counts them)
//                    u32 entries      at most 4096, each:
//                      u8  kind       1 value (CPU state), 2 text, 3 buffer (GPU state)
//                      str name       at most 256 bytes, unique
//                      u64 bytes, then that many bytes
//   (str: u32 length, then the bytes)
//
// The parser trusts nothing: every length is checked against the bytes left and its limit before
// anything is allocated, and every failure is one line naming the file, the field or offset and
// the problem ("run.ckpt: checksum mismatch (payload corrupt)").
//
// Writing is atomic: the bytes go to "<file>.tmp" in the same folder, which is fsynced and renamed
// over the file, then the folder is fsynced. A crash at any point leaves the previous checkpoint
// (or none) whole, never a mix.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace tidepool::io {

inline constexpr char kCheckpointMagic[8] = {'T', 'I', 'D', 'E', 'P', 'O', 'O', 'L'};
inline constexpr std::uint32_t kCheckpointVersion = 1;
inline constexpr std::size_t kCheckpointHeaderBytes = 24;
inline constexpr std::size_t kMaxModelName = 64, kMaxSceneName = 4096, kMaxParamsText = std::size_t(16) << 20;
inline constexpr std::size_t kMaxEntries = 4096, kMaxEntryName = 256;

enum class EntryKind : std::uint8_t { Value = 1, Text = 2, Buffer = 3 };

struct CheckpointEntry {
  EntryKind kind = EntryKind::Value;
  std::string name;                 // "balls.positions", "watch.frames"
  std::vector<std::uint8_t> bytes;  // a value's little-endian bytes, a text's characters, a buffer's contents
};

struct Checkpoint {
  std::string model;   // the scene's model
  std::string scene;   // the scene file it ran
  std::string params;  // JSON text
  double time = 0;
  std::uint64_t steps = 0;
  std::vector<CheckpointEntry> entries;

  const CheckpointEntry* find(const std::string& name) const;  // nullptr: none
};

std::uint32_t crc32(std::span<const std::uint8_t> bytes);  // IEEE 802.3 (zlib's crc32)

std::vector<std::uint8_t> encodeCheckpoint(const Checkpoint& c);  // throws Error (a field over its limit)
// Throws Error "<where>: ..." naming what is wrong: a bad magic, another format version, a
// truncated or overlong file, a checksum mismatch, a field over its limit or past the end.
Checkpoint parseCheckpoint(std::span<const std::uint8_t> bytes, const std::string& where);
// The whole file, parsed (where = the path as given). A missing file is one line too.
Checkpoint readCheckpointFile(const std::filesystem::path& file);

// The points of an atomic write at which a test may stop it as a crash would.
enum class WriteStep {
  HalfWritten,   // half the bytes are in the temporary file
  BeforeRename,  // all written and fsynced, not yet renamed over the file
};
// Writes `bytes` to `file` atomically (see above); `crashPoint` (tests) is called at each step
// and may end the process there. Throws Error naming the file and the system's reason.
void writeFileAtomically(const std::filesystem::path& file, std::span<const std::uint8_t> bytes,
                         const std::function<void(WriteStep)>& crashPoint = {});
std::filesystem::path temporaryPath(const std::filesystem::path& file);  // "<file>.tmp"

}  // namespace tidepool::io
