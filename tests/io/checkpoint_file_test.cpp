// The checkpoint file format alone (no GL): what it round-trips, what it refuses and how it says
// so, and the atomic writer, crashed on purpose between its steps.
#include "io/checkpoint_file.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "support/error_of.h"
#include "support/gl_test.h"

using namespace tidepool;
using test::errorOf;

namespace {

io::Checkpoint sample() {
  io::Checkpoint c;
  c.model = "balls";
  c.scene = "assets/scenes/dam-break.json";
  c.params = R"({"engine": {"dt": 0.0005}})";
  c.time = 1.25;
  c.steps = 2500;
  c.entries.push_back({io::EntryKind::Value, "model.count", {0x10, 0x27, 0, 0, 0, 0, 0, 0}});
  c.entries.push_back({io::EntryKind::Text, "model.rng", {'1', ' ', '2'}});
  std::vector<std::uint8_t> buffer(4000);
  for (std::size_t i = 0; i < buffer.size(); ++i) buffer[i] = std::uint8_t(i * 7);
  c.entries.push_back({io::EntryKind::Buffer, "model.positions", buffer});
  c.entries.push_back({io::EntryKind::Buffer, "model.empty", {}});
  return c;
}

std::vector<std::uint8_t> readBytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void putU32(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) b[at + std::size_t(i)] = std::uint8_t(v >> (8 * i));
}
void putU64(std::vector<std::uint8_t>& b, std::size_t at, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) b[at + std::size_t(i)] = std::uint8_t(v >> (8 * i));
}
// After editing the payload: the checksum it now has, so that the parser reaches the field.
void reseal(std::vector<std::uint8_t>& b) {
  putU32(b, 12, io::crc32(std::span<const std::uint8_t>(b).subspan(io::kCheckpointHeaderBytes)));
}

}  // namespace

TEST(CheckpointFile, RoundTripsEveryField) {
  const io::Checkpoint c = sample();
  const std::vector<std::uint8_t> bytes = io::encodeCheckpoint(c);
  const io::Checkpoint back = io::parseCheckpoint(bytes, "x.ckpt");
  EXPECT_EQ(back.model, c.model);
  EXPECT_EQ(back.scene, c.scene);
  EXPECT_EQ(back.params, c.params);
  EXPECT_EQ(back.time, c.time);
  EXPECT_EQ(back.steps, c.steps);
  ASSERT_EQ(back.entries.size(), c.entries.size());
  for (std::size_t i = 0; i < c.entries.size(); ++i) {
    EXPECT_EQ(back.entries[i].kind, c.entries[i].kind);
    EXPECT_EQ(back.entries[i].name, c.entries[i].name);
    EXPECT_EQ(back.entries[i].bytes, c.entries[i].bytes);
  }
  ASSERT_NE(back.find("model.positions"), nullptr);
  EXPECT_EQ(back.find("model.nothing"), nullptr);
}

TEST(CheckpointFile, HeaderIsTheDocumentedLayout) {
  const std::vector<std::uint8_t> bytes = io::encodeCheckpoint(sample());
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 8), "TIDEPOOL");
  EXPECT_EQ(bytes[8], io::kCheckpointVersion);
  std::uint64_t payload = 0;
  for (int i = 0; i < 8; ++i) payload |= std::uint64_t(bytes[16 + std::size_t(i)]) << (8 * i);
  EXPECT_EQ(payload + io::kCheckpointHeaderBytes, bytes.size());
  // zlib's CRC-32 of "123456789" is cbf43926
  const std::string check = "123456789";
  EXPECT_EQ(io::crc32(std::span(reinterpret_cast<const std::uint8_t*>(check.data()), check.size())), 0xcbf43926u);
}

TEST(CheckpointFile, EveryTruncationIsRefusedWithWhereItEnds) {
  const std::vector<std::uint8_t> bytes = io::encodeCheckpoint(sample());
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    const std::string e = errorOf([&] { io::parseCheckpoint(std::span(bytes).first(n), "run.ckpt"); });
    ASSERT_NE(e, "") << "a prefix of " << n << " bytes was accepted";
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    EXPECT_EQ(e.rfind("run.ckpt", 0), 0u) << e;
    if (n >= 8) EXPECT_NE(e.find("truncated at byte " + std::to_string(n) + " of"), std::string::npos) << e;
  }
  EXPECT_EQ(errorOf([&] { io::parseCheckpoint(std::span(bytes).first(100), "run.ckpt"); }),
            "run.ckpt: truncated at byte 100 of " + std::to_string(bytes.size()));
}

// Each of the file's bits flipped alone (a pure CPU parse of a small file: fast): one in the
// payload is a checksum mismatch; one in the header is refused too (magic, version, checksum, size).
TEST(CheckpointFile, EveryFlippedBitIsRefusedAndOfThePayloadIsAChecksumMismatch) {
  const std::vector<std::uint8_t> good = io::encodeCheckpoint(sample());
  std::vector<std::uint8_t> bad = good;
  for (std::size_t at = 0; at < good.size(); ++at)
    for (int bit = 0; bit < 8; ++bit) {
      bad[at] ^= std::uint8_t(1 << bit);
      const std::string e = errorOf([&] { io::parseCheckpoint(bad, "run.ckpt"); });
      bad[at] = good[at];
      if (at < io::kCheckpointHeaderBytes)
        EXPECT_EQ(e.rfind("run.ckpt", 0), 0u) << "header byte " << at << " bit " << bit << ": " << e;
      else
        EXPECT_NE(e.find("run.ckpt: checksum mismatch (payload corrupt"), std::string::npos)
            << "byte " << at << " bit " << bit << ": " << e;
    }
}

TEST(CheckpointFile, OtherVersionsMagicAndTrailingBytesAreRefused) {
  std::vector<std::uint8_t> bytes = io::encodeCheckpoint(sample());
  std::vector<std::uint8_t> v3 = bytes;
  putU32(v3, 8, 3);
  EXPECT_EQ(errorOf([&] { io::parseCheckpoint(v3, "run.ckpt"); }), "run.ckpt: format version 3, this build reads 1");
  std::vector<std::uint8_t> png = bytes;
  png[0] = 0x89;
  EXPECT_NE(errorOf([&] { io::parseCheckpoint(png, "x.png"); }).find("x.png: not a tidepool checkpoint"),
            std::string::npos);
  std::vector<std::uint8_t> longer = bytes;
  longer.push_back(0);
  EXPECT_NE(errorOf([&] { io::parseCheckpoint(longer, "run.ckpt"); }).find("1 bytes after the end"), std::string::npos);
  std::vector<std::uint8_t> huge = bytes;
  putU64(huge, 16, ~std::uint64_t(0));  // a payload size that would overflow the total
  EXPECT_NE(errorOf([&] { io::parseCheckpoint(huge, "run.ckpt"); }).find("truncated at byte"), std::string::npos);
}

TEST(CheckpointFile, LengthsAreCheckedAgainstTheirLimitsAndTheBytesLeft) {
  const std::vector<std::uint8_t> good = io::encodeCheckpoint(sample());
  const std::size_t model = io::kCheckpointHeaderBytes;  // u32 length of the model name
  std::vector<std::uint8_t> b = good;
  putU32(b, model, 1000);
  reseal(b);
  EXPECT_EQ(errorOf([&] { io::parseCheckpoint(b, "run.ckpt"); }),
            "run.ckpt: model name at byte 24: length 1000 is more than the limit 64");
  b = good;
  putU32(b, model, 60);  // within the limit, but it runs into the next fields: still parsed bytes, then a bad length
  reseal(b);
  EXPECT_NE(errorOf([&] { io::parseCheckpoint(b, "run.ckpt"); }), "");
  // The entry count, then a buffer's length claimed larger than what is left.
  const io::Checkpoint c = sample();
  const std::size_t entriesAt = model + 4 + c.model.size() + 4 + c.scene.size() + 4 + c.params.size() + 16;
  b = good;
  putU32(b, entriesAt, 100000);
  reseal(b);
  EXPECT_EQ(errorOf([&] { io::parseCheckpoint(b, "run.ckpt"); }), "run.ckpt: 100000 entries, more than the limit 4096");
  const std::size_t firstLength = entriesAt + 4 + 1 + 4 + c.entries[0].name.size();
  b = good;
  putU64(b, firstLength, std::uint64_t(1) << 40);
  reseal(b);
  const std::string e = errorOf([&] { io::parseCheckpoint(b, "run.ckpt"); });
  EXPECT_NE(e.find("run.ckpt: entry 'model.count' (value) at byte " + std::to_string(firstLength + 8) +
                   ": needs 1099511627776 bytes, only"),
            std::string::npos)
      << e;
  b = good;
  b[entriesAt + 4] = 9;  // the first entry's kind
  reseal(b);
  EXPECT_NE(errorOf([&] { io::parseCheckpoint(b, "run.ckpt"); }).find("9 is not 1 (value), 2 (text) or 3 (buffer)"),
            std::string::npos);
}

TEST(CheckpointFile, DuplicateEntriesAndOverlongFieldsAreRefused) {
  io::Checkpoint c = sample();
  c.entries.push_back(c.entries[0]);
  EXPECT_NE(errorOf([&] { io::parseCheckpoint(io::encodeCheckpoint(c), "d.ckpt"); }).find("a second entry named"),
            std::string::npos);
  c = sample();
  c.model = std::string(100, 'x');
  EXPECT_NE(errorOf([&] { io::encodeCheckpoint(c); }).find("model name of 100 bytes, at most 64"), std::string::npos);
}

TEST(CheckpointFile, AMissingOrFolderFileIsOneLine) {
  test::TempDir dir;
  EXPECT_EQ(errorOf([&] { io::readCheckpointFile(dir / "none.ckpt"); }),
            "checkpoint not found: '" + (dir / "none.ckpt").string() + "'");
  EXPECT_NE(errorOf([&] { io::readCheckpointFile(dir.path()); }).find("is a folder"), std::string::npos);
}

TEST(CheckpointFile, AtomicWriteReplacesTheFileAndLeavesNoTemporary) {
  test::TempDir dir;
  const std::filesystem::path file = dir / "run.ckpt";
  io::Checkpoint c = sample();
  io::writeFileAtomically(file, io::encodeCheckpoint(c));
  c.time = 2.5;
  io::writeFileAtomically(file, io::encodeCheckpoint(c));
  EXPECT_EQ(io::readCheckpointFile(file).time, 2.5);
  EXPECT_FALSE(std::filesystem::exists(io::temporaryPath(file)));
  EXPECT_NE(errorOf([&] {
              io::writeFileAtomically(dir / "no/such/folder/x.ckpt", io::encodeCheckpoint(c));
            }).find("cannot write checkpoint"),
            std::string::npos);
}

// A process killed between the steps of a save (here: it exits on the spot, as a crash would,
// leaving whatever it wrote) leaves the previous checkpoint whole and loadable; the next save
// overwrites the stale temporary file.
TEST(CheckpointFile, ASaveInterruptedAtAnyStepLeavesTheOldFileLoadable) {
  GTEST_FLAG_SET(death_test_style, "fast");  // fork right here: the child writes into this test's folder
  for (io::WriteStep step : {io::WriteStep::HalfWritten, io::WriteStep::BeforeRename}) {
    test::TempDir dir;
    const std::filesystem::path file = dir / "run.ckpt";
    io::Checkpoint old = sample();
    io::writeFileAtomically(file, io::encodeCheckpoint(old));
    const std::vector<std::uint8_t> before = readBytes(file);
    io::Checkpoint next = sample();
    next.time = 9.0;
    next.entries[2].bytes.assign(100000, 0xAB);
    EXPECT_EXIT(io::writeFileAtomically(file, io::encodeCheckpoint(next),
                                        [step](io::WriteStep at) {
                                          if (at == step) std::_Exit(3);
                                        }),
                ::testing::ExitedWithCode(3), "");
    EXPECT_EQ(readBytes(file), before);  // untouched, byte for byte
    EXPECT_EQ(io::readCheckpointFile(file).time, 1.25);
    ASSERT_TRUE(std::filesystem::exists(io::temporaryPath(file)));  // what the crash left behind
    if (step == io::WriteStep::HalfWritten)
      EXPECT_NE(errorOf([&] { io::readCheckpointFile(io::temporaryPath(file)); }).find("truncated"), std::string::npos);
    io::writeFileAtomically(file, io::encodeCheckpoint(next));
    EXPECT_EQ(io::readCheckpointFile(file).time, 9.0);
    EXPECT_FALSE(std::filesystem::exists(io::temporaryPath(file)));
  }
}
