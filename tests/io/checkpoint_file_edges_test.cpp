// What the checkpoint reader and writer do with files that are not plain checkpoints: a pipe, a
// device, a sparse file of a gigabyte, a header stating more than the limit (the reader looks at
// the 24-byte header before it reads or allocates the payload); a folder, a pipe or a symbolic
// link where a checkpoint is to be written.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <fstream>

#include "io/checkpoint_file.h"
#include "io/checkpoint_path.h"
#include "support/error_of.h"
#include "support/gl_test.h"

using namespace tidepool;
using test::errorOf;

namespace {

io::Checkpoint small() {
  io::Checkpoint c;
  c.model = "blank";
  c.time = 0.5;
  c.entries.push_back({io::EntryKind::Value, "model.count", {1, 0, 0, 0, 0, 0, 0, 0}});
  return c;
}

// A file of `size` bytes that are all zeros but for `head` at the start (sparse: no disk used).
void sparseFile(const std::filesystem::path& file, const std::vector<std::uint8_t>& head, std::uint64_t size) {
  {
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(head.data()), std::streamsize(head.size()));
  }
  std::filesystem::resize_file(file, size);
}

std::vector<std::uint8_t> headerStating(std::uint64_t payloadBytes) {
  std::vector<std::uint8_t> h = io::encodeCheckpoint(small());
  h.resize(io::kCheckpointHeaderBytes);
  for (int i = 0; i < 8; ++i) h[16 + std::size_t(i)] = std::uint8_t(payloadBytes >> (8 * i));
  return h;
}

}  // namespace

TEST(CheckpointFileEdges, APipeOrADeviceIsRefusedWithoutWaitingOrReading) {
  test::TempDir dir;
  const std::filesystem::path fifo = dir / "pipe.ckpt";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(errorOf([&] { io::readCheckpointFile(fifo); }),
            "'" + fifo.string() + "' is not a regular file (a device, pipe or socket): give a checkpoint file");
  EXPECT_EQ(errorOf([&] { io::readCheckpointFile("/dev/zero"); }),
            "'/dev/zero' is not a regular file (a device, pipe or socket): give a checkpoint file");
}

TEST(CheckpointFileEdges, TheHeaderIsCheckedBeforeThePayloadIsRead) {
  test::TempDir dir;
  const std::filesystem::path zeros = dir / "zeros.ckpt";
  sparseFile(zeros, {}, std::uint64_t(1) << 30);  // 1 GiB, no magic
  EXPECT_EQ(errorOf([&] { io::readCheckpointFile(zeros); }),
            zeros.string() + ": not a tidepool checkpoint (the file does not start with \"TIDEPOOL\")");
  // A header stating a payload the file does not have.
  const std::filesystem::path lying = dir / "lying.ckpt";
  sparseFile(lying, headerStating(100), 1000);
  EXPECT_EQ(errorOf([&] { io::readCheckpointFile(lying); }),
            lying.string() + ": 876 bytes after the end of the checkpoint (byte 124)");
  // A header that matches a file larger than any state: refused before the payload is allocated.
  const std::uint64_t huge = io::kMaxCheckpointFileBytes + 4096;
  const std::filesystem::path big = dir / "big.ckpt";
  sparseFile(big, headerStating(huge - io::kCheckpointHeaderBytes), huge);
  EXPECT_EQ(errorOf([&] { io::readCheckpointFile(big); }),
            "'" + big.string() + "' is 32768.0 MiB, larger than the 32768 MiB allowed for a checkpoint");
}

TEST(CheckpointFileEdges, OnlyARegularFileOrANewNameIsWritten) {
  test::TempDir dir;
  const std::vector<std::uint8_t> bytes = io::encodeCheckpoint(small());
  const std::filesystem::path fifo = dir / "pipe.ckpt";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(errorOf([&] { io::writeFileAtomically(fifo, bytes); }),
            "cannot write checkpoint '" + fifo.string() +
                "': it is a device, pipe or socket; give a regular file or a new name");
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));  // not replaced
  EXPECT_EQ(errorOf([&] { io::writeFileAtomically(dir.path(), bytes); }),
            "cannot write checkpoint '" + dir.path().string() + "': it is a folder; give a regular file or a new name");
  EXPECT_TRUE(std::filesystem::is_directory(dir.path()));
  const std::filesystem::path toPipe = dir / "to-pipe.ckpt";
  std::filesystem::create_symlink(fifo, toPipe);
  EXPECT_NE(
      errorOf([&] { io::writeFileAtomically(toPipe, bytes); }).find("a symbolic link to a device, pipe or socket"),
      std::string::npos);
  const std::filesystem::path dangling = dir / "dangling.ckpt";
  std::filesystem::create_symlink(dir / "nothing/here", dangling);
  EXPECT_NE(errorOf([&] { io::writeFileAtomically(dangling, bytes); }).find("a symbolic link to nothing"),
            std::string::npos);
  // A stale temporary name that is a pipe is neither waited on nor followed.
  const std::filesystem::path file = dir / "run.ckpt";
  ASSERT_EQ(::mkfifo(io::temporaryPath(file).c_str(), 0600), 0);
  EXPECT_NE(errorOf([&] { io::writeFileAtomically(file, bytes); }).find("cannot write checkpoint"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(file));
}

TEST(CheckpointFileEdges, ASymbolicLinkIsWrittenThroughAndStays) {
  test::TempDir dir;
  std::filesystem::create_directory(dir / "keep");
  const std::filesystem::path target = dir / "keep/real.ckpt", link = dir / "run.ckpt";
  io::writeFileAtomically(target, io::encodeCheckpoint(small()));
  std::filesystem::create_symlink(target, link);
  io::Checkpoint later = small();
  later.time = 2.0;
  io::writeFileAtomically(link, io::encodeCheckpoint(later));
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_EQ(io::readCheckpointFile(target).time, 2.0);
  EXPECT_EQ(io::checkpointTarget(link), std::filesystem::canonical(target));
  EXPECT_FALSE(std::filesystem::exists(io::temporaryPath(target)));
  EXPECT_FALSE(std::filesystem::exists(io::temporaryPath(link)));
}
