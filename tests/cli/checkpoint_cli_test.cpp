// Checkpoints through the program: render 41 frames straight, or 21 with a checkpoint and 20 more
// resumed from it (numbered 21 to 40), and get the same state and the same frames; periodic checkpoints beside
// the output; bad checkpoints refused in one line; the window's autosave and --resume.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "io/checkpoint_file.h"
#include "io/png.h"
#include "support/checkpoint_edit.h"
#include "support/gl_test.h"
#include "support/one_line_error.h"

using namespace tidepool;
using test::runTidepool;

namespace {

// Rain (a random generator), a scheduled drop after the split and a moving sphere: state that is
// not in the height buffer alone.
const char* kRipples = R"({"name": "r", "model": "ripples", "params": {"width": 48, "height": 32,
  "touch": {"rain": 15}, "sphere": {"enabled": true}, "drops": [{"time": 0.9, "x": 0.5, "y": 0.5}]},
  "clip": {"fps": 30, "width": 64, "height": 40}})";

std::map<std::string, std::vector<std::uint8_t>> buffersOf(const std::filesystem::path& file) {
  std::map<std::string, std::vector<std::uint8_t>> out;
  for (const io::CheckpointEntry& e : io::readCheckpointFile(file).entries)
    if (e.name != "watch.frames") out[e.name] = e.bytes;
  return out;
}

void render(const std::vector<std::string>& args) {
  std::vector<std::string> all = {"render"};
  all.insert(all.end(), args.begin(), args.end());
  all.push_back("--quiet");
  const auto r = runTidepool(all);
  ASSERT_EQ(r.exitCode, 0) << r.err;
}

}  // namespace

TEST(CheckpointCli, ResumedRenderEqualsTheStraightOne) {
  test::TempDir dir;
  dir.write("r.json", kRipples);
  const std::string scene = (dir / "r.json").string();
  render({scene, "--frames", "41", "--out", (dir / "straight").string(), "--checkpoint", (dir / "s.ckpt").string()});
  render({scene, "--frames", "21", "--out", (dir / "first").string(), "--checkpoint", (dir / "half.ckpt").string()});
  render({scene, "--resume", (dir / "half.ckpt").string(), "--frames", "20", "--out", (dir / "second").string(),
          "--checkpoint", (dir / "end.ckpt").string()});
  EXPECT_EQ(io::readCheckpointFile(dir / "s.ckpt").time, io::readCheckpointFile(dir / "end.ckpt").time);
  EXPECT_TRUE(buffersOf(dir / "s.ckpt") == buffersOf(dir / "end.ckpt"));
  EXPECT_FALSE(buffersOf(dir / "half.ckpt") == buffersOf(dir / "end.ckpt"));
  // The resumed render goes on after the checkpoint's frame (20), a step a frame: frames 21 to 40,
  // each the straight run's frame of that number; the two folders join into the straight clip.
  for (int i = 0; i <= 40; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", i);
    EXPECT_EQ(std::filesystem::exists(dir / "first" / name), i <= 20) << name;
    EXPECT_EQ(std::filesystem::exists(dir / "second" / name), i > 20) << name;
  }
  for (const char* name : {"frame_00021.png", "frame_00030.png", "frame_00040.png"})
    EXPECT_EQ(io::readPng(dir / "straight" / name).rgba, io::readPng(dir / "second" / name).rgba) << name;
  EXPECT_EQ(io::readPng(dir / "straight/frame_00020.png").rgba, io::readPng(dir / "first/frame_00020.png").rgba);
}

// A checkpoint holds the number of its frame: resumed, a render numbers its frames on from the
// next one, whatever it was told to write; a hostile frame number is refused in one line.
TEST(CheckpointCli, ResumeNumbersOnFromTheCheckpointsFrame) {
  test::TempDir dir;
  dir.write("r.json", kRipples);
  const std::string scene = (dir / "r.json").string();
  render({scene, "--frames", "12", "--out", (dir / "a").string(), "--checkpoint", (dir / "a.ckpt").string()});
  std::uint64_t saved = 0;
  const io::Checkpoint a = io::readCheckpointFile(dir / "a.ckpt");
  ASSERT_NE(a.find("clip.frame"), nullptr);
  std::memcpy(&saved, a.find("clip.frame")->bytes.data(), sizeof saved);
  EXPECT_EQ(saved, 11u);
  const auto resumed = [&](const std::string& ckpt, const std::string& out) {
    return runTidepool({"render", scene, "--frames", "3", "--out", (dir / out).string(), "--resume",
                        (dir / ckpt).string(), "--quiet"});
  };
  auto r = resumed("a.ckpt", "b");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("frames from 12"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(frames 12 to 14)"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "b/frame_00014.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "b/frame_00000.png"));
  test::editCheckpointFile(dir / "a.ckpt", dir / "eight.ckpt",
                           [](io::Checkpoint& c) { test::setValue(c, "clip.frame", std::uint64_t(8)); });
  r = resumed("eight.ckpt", "c");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "c/frame_00009.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "c/frame_00011.png"));
  test::editCheckpointFile(dir / "a.ckpt", dir / "far.ckpt",
                           [](io::Checkpoint& c) { test::setValue(c, "clip.frame", std::uint64_t(1) << 40); });
  test::expectOneLineError({"render", scene, "--out", (dir / "d").string(), "--resume", (dir / "far.ckpt").string()},
                           "far.ckpt: entry 'clip.frame' = 1099511627776 is more than 1000000000 frames");
}

TEST(CheckpointCli, CheckpointEverySavesBesideTheOutputAndAfterTheLastFrame) {
  test::TempDir dir;
  dir.write("r.json", kRipples);
  const auto r = runTidepool({"render", (dir / "r.json").string(), "--frames", "31", "--out", (dir / "out").string(),
                              "--checkpoint-every", "0.25", "--quiet"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("wrote checkpoint " + (dir / "out.ckpt").string() + " at t = 1.0"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(4 saved)"), std::string::npos) << r.err;  // 0.25, 0.5, 0.75 s and the end
  EXPECT_NEAR(io::readCheckpointFile(dir / "out.ckpt").time, 1.0, 1e-9);
  EXPECT_FALSE(std::filesystem::exists(io::temporaryPath(dir / "out.ckpt")));
  test::expectOneLineError({"render", "blank", "--out", (dir / "b").string(), "--checkpoint-every", "0"},
                           "--checkpoint-every", 2);
}

TEST(CheckpointCli, BadCheckpointsAreOneLineErrors) {
  test::TempDir dir;
  dir.write("r.json", kRipples);
  dir.write("s.json", R"({"model": "swarm", "params": {"particles": 1000}})");
  const std::string out = (dir / "o").string();
  test::expectOneLineError({"render", "blank", "--out", out, "--resume", (dir / "none.ckpt").string()},
                           "checkpoint not found: '" + (dir / "none.ckpt").string() + "'");
  render({(dir / "r.json").string(), "--frames", "3", "--out", out, "--checkpoint", (dir / "r.ckpt").string()});
  test::expectOneLineError({"render", (dir / "s.json").string(), "--out", out, "--resume", (dir / "r.ckpt").string()},
                           (dir / "r.ckpt").string() + " is a ripples checkpoint (of " + (dir / "r.json").string() +
                               "), the scene runs swarm");
  std::ifstream in(dir / "r.ckpt", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  dir.write("cut.ckpt", bytes.substr(0, 1000));
  test::expectOneLineError({"render", (dir / "r.json").string(), "--out", out, "--resume", (dir / "cut.ckpt").string()},
                           "cut.ckpt: truncated at byte 1000 of " + std::to_string(bytes.size()));
  bytes[bytes.size() / 2] ^= 0x10;
  dir.write("flip.ckpt", bytes);
  test::expectOneLineError(
      {"render", (dir / "r.json").string(), "--out", out, "--resume", (dir / "flip.ckpt").string()},
      "flip.ckpt: checksum mismatch (payload corrupt");
  bytes[8] = 2;
  dir.write("v2.ckpt", bytes);
  test::expectOneLineError({"render", (dir / "r.json").string(), "--out", out, "--resume", (dir / "v2.ckpt").string()},
                           "v2.ckpt: format version 2, this build reads 1");
}

TEST(CheckpointCli, RunWithoutADisplayResumesAndCheckpoints) {
  test::TempDir dir;
  dir.write("r.json", kRipples);
  render({(dir / "r.json").string(), "--frames", "5", "--out", (dir / "a").string(), "--checkpoint",
          (dir / "a.ckpt").string()});
  const auto r = runTidepool({"run", (dir / "r.json").string(), "--frames", "5", "--out", (dir / "run").string(),
                              "--resume", (dir / "a.ckpt").string(), "--checkpoint", (dir / "b.ckpt").string()},
                             {"DISPLAY=", "WAYLAND_DISPLAY="});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("resumed from " + (dir / "a.ckpt").string()), std::string::npos) << r.err;
  EXPECT_NEAR(io::readCheckpointFile(dir / "b.ckpt").time, 9.0 / 30, 1e-9);  // 4 steps, then 5 more
}

TEST(CheckpointCli, TheWindowAutosavesAndResumesUnderXvfb) {
  ASSERT_EQ(test::runProcess({"sh", "-c", "command -v xvfb-run"}).exitCode, 0) << "xvfb-run is needed";
  test::TempDir dir;
  dir.write("r.json", kRipples);
  const std::string ckpt = (dir / "w.ckpt").string();
  const std::vector<std::string> window = {"xvfb-run",
                                           "-a",
                                           "-s",
                                           "-screen 0 640x480x24",
                                           TIDEPOOL_EXE,
                                           "run",
                                           (dir / "r.json").string(),
                                           "--backend",
                                           "window",
                                           "--size",
                                           "320x240"};
  auto args = window;
  for (const char* a : {"--frames", "20", "--checkpoint-every", "0.25", "--checkpoint"}) args.push_back(a);
  args.push_back(ckpt);
  auto r = test::runProcess(args);
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  // 20 frames of the scene's 1/30 s, as `render` advances them: autosaves at 8/30 and 15/30 s.
  EXPECT_NE(r.err.find("autosaved " + ckpt + " at t = 0.267 s"), std::string::npos) << r.err;
  EXPECT_NEAR(io::readCheckpointFile(ckpt).time, 0.5, 1e-9);
  // Resumed, the window goes on from the checkpoint's state: its autosaves (every frame) end
  // where a headless run resumed from the same file for as many steps ends, entry for entry.
  const std::string resumed = (dir / "w2.ckpt").string();
  args = window;
  for (const char* a : {"--frames", "4", "--checkpoint-every", "0.001", "--checkpoint"}) args.push_back(a);
  for (const std::string& a : {resumed, std::string("--resume"), ckpt}) args.push_back(a);
  r = test::runProcess(args);
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const io::Checkpoint after = io::readCheckpointFile(resumed);
  const int steps = int(std::lround((after.time - 0.5) * 30));
  ASSERT_GE(steps, 1) << "the resumed window saved at t = " << after.time;
  const auto headless = runTidepool({"run", (dir / "r.json").string(), "--frames", std::to_string(steps), "--out",
                                     (dir / "h").string(), "--resume", ckpt, "--checkpoint", (dir / "h.ckpt").string()},
                                    {"DISPLAY=", "WAYLAND_DISPLAY="});
  ASSERT_EQ(headless.exitCode, 0) << headless.err;
  const io::Checkpoint straight = io::readCheckpointFile(dir / "h.ckpt");
  EXPECT_EQ(after.time, straight.time);
  EXPECT_EQ(after.steps, straight.steps);
  std::size_t compared = 0;
  for (const io::CheckpointEntry& e : straight.entries)
    if (e.name.rfind("watch.", 0) != 0) {
      const io::CheckpointEntry* w = after.find(e.name);
      ASSERT_NE(w, nullptr) << e.name;
      EXPECT_TRUE(w->bytes == e.bytes) << e.name;
      ++compared;
    }
  EXPECT_NE(after.find("model.state"), nullptr);
  EXPECT_GT(compared, 3u);
  EXPECT_FALSE(io::readCheckpointFile(ckpt).find("model.state")->bytes == after.find("model.state")->bytes);
}

TEST(CheckpointCli, ResumeRefusesPipesDevicesAndHostileValuesInOneLine) {
  test::TempDir dir;
  dir.write("r.json", kRipples);
  const std::string scene = (dir / "r.json").string(), out = (dir / "o").string();
  const std::filesystem::path fifo = dir / "pipe.ckpt";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  test::expectOneLineError({"render", scene, "--out", out, "--resume", fifo.string()},
                           "'" + fifo.string() + "' is not a regular file (a device, pipe or socket)");
  test::expectOneLineError({"render", scene, "--out", out, "--resume", "/dev/zero"},
                           "'/dev/zero' is not a regular file (a device, pipe or socket)");
  render({scene, "--frames", "3", "--out", out, "--checkpoint", (dir / "r.ckpt").string()});
  test::editCheckpointFile(dir / "r.ckpt", dir / "debt.ckpt",
                           [](io::Checkpoint& c) { test::setValue(c, "model.rain_debt", double(INFINITY)); });
  test::expectOneLineError({"render", scene, "--out", out, "--resume", (dir / "debt.ckpt").string()},
                           "debt.ckpt: entry 'model.rain_debt' = inf is not a finite number");
}

TEST(CheckpointCli, TheCheckpointPathIsARegularFileANewNameOrALinkToOne) {
  test::TempDir dir;
  dir.write("r.json", kRipples);
  const std::string scene = (dir / "r.json").string(), out = (dir / "o").string();
  const std::filesystem::path fifo = dir / "pipe.ckpt";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  test::expectOneLineError({"render", scene, "--frames", "2", "--out", out, "--checkpoint", fifo.string()},
                           "cannot write checkpoint '" + fifo.string() + "': it is a device, pipe or socket");
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
  std::filesystem::create_directory(dir / "folder");
  test::expectOneLineError({"render", scene, "--frames", "2", "--out", out, "--checkpoint", (dir / "folder").string()},
                           "cannot write checkpoint '" + (dir / "folder").string() + "': it is a folder");
  dir.write("real.ckpt", "old");
  std::filesystem::create_symlink(dir / "real.ckpt", dir / "link.ckpt");
  render({scene, "--frames", "2", "--out", out, "--checkpoint", (dir / "link.ckpt").string()});
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.ckpt"));
  EXPECT_NEAR(io::readCheckpointFile(dir / "real.ckpt").time, 1.0 / 30, 1e-9);
}
