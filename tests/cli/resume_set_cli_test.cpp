// --set on a resumed run: live keys (the view, the physics the window edits mid-run) apply on top
// of the checkpoint's parameters, keys the checkpoint fixes are refused before any work; a bad
// --set value is blamed on that --set, not on the scene file; stale frames get a warning.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "io/png.h"
#include "support/gl_test.h"
#include "support/one_line_error.h"

using namespace tidepool;
using test::runTidepool;

namespace {

// Refined twice: engine.dt as a fresh run takes it is the file's / 2.
const char* kSmallDam = R"({"model": "balls", "params": {
    "particles": {"radius": 0.04, "domain_max": [0.4, 0.2, 0.3], "fill": "block", "fill_max": [0.1, 0.2, 0.2],
                  "resolution": 2},
    "engine": {"dt": 0.001, "substeps": 1, "contact_time": 0.01}},
    "clip": {"frames": 2, "width": 64, "height": 36}})";

std::string fileText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

test::ProcessResult render(std::vector<std::string> args) {
  args.insert(args.begin(), "render");
  args.push_back("--quiet");
  return runTidepool(args);
}

}  // namespace

TEST(ResumeSetCli, LiveKeysApplyOnTopOfTheCheckpoint) {
  test::TempDir dir;
  dir.write("dam.json", kSmallDam);
  const std::string scene = (dir / "dam.json").string(), start = (dir / "start.ckpt").string();
  auto r = render({scene, "--frames", "2", "--out", (dir / "a").string(), "--checkpoint", start});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  r = render({scene, "--resume", start, "--frames", "1", "--out", (dir / "plain").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  r = render({scene, "--resume", start, "--frames", "1", "--out", (dir / "set").string(), "--checkpoint",
              (dir / "set.ckpt").string(), "--set", "view.mode=water", "--set", "engine.damping=1", "--set",
              "engine.dt=0.0008"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // The water look: another picture of the same state.
  EXPECT_NE(io::readPng(dir / "plain/frame_00002.png").rgba, io::readPng(dir / "set/frame_00002.png").rgba);
  // The parameters run on: the checkpoint's, with the keys set as a fresh run takes them (dt refined).
  const std::string before = fileText(start), after = fileText(dir / "set.ckpt");
  EXPECT_NE(before.find("\"mode\":\"balls\""), std::string::npos);
  EXPECT_NE(after.find("\"mode\":\"water\""), std::string::npos);
  EXPECT_NE(after.find("\"damping\":1.0"), std::string::npos);
  EXPECT_NE(after.find("\"dt\":0.000399999"), std::string::npos) << "0.0008 / 2 in float";
  EXPECT_NE(after.find("\"resolution\":2.0"), std::string::npos);
}

TEST(ResumeSetCli, KeysTheCheckpointFixesAreRefused) {
  test::TempDir dir;
  dir.write("dam.json", kSmallDam);
  const std::string scene = (dir / "dam.json").string(), out = (dir / "f").string();
  // Refused before any work: the checkpoint is not even read, no folder is made.
  const std::string ckpt = (dir / "dam.ckpt").string();
  const std::string tail =
      "and cannot be applied to a resumed run (checkpoint " + ckpt + "); drop it or start without --resume";
  test::expectOneLineError({"render", scene, "--resume", ckpt, "--out", out, "--set", "particles.radius=0.03"},
                           "--set particles.radius: changes the simulation state (the particles' count, size, "
                           "domain and initial water) " +
                               tail);
  test::expectOneLineError({"render", scene, "--resume", ckpt, "--out", out, "--set", "particles={\"fill\":\"slab\"}"},
                           "--set particles.fill: changes the simulation state");
  test::expectOneLineError({"render", scene, "--resume", ckpt, "--out", out, "--resolution", "3"},
                           "--resolution: changes the simulation state (the particles' count, size, domain and "
                           "initial water) " +
                               tail);
  test::expectOneLineError({"render", scene, "--resume", ckpt, "--out", out, "--fit-gpu"},
                           "--fit-gpu: changes the simulation state (it picks particles.resolution) " + tail);
  test::expectOneLineError({"render", "life", "--resume", ckpt, "--out", out, "--rules", "orbits"},
                           "--rules: changes the simulation state (life's rules");
  test::expectOneLineError({"render", "life", "--resume", ckpt, "--out", out, "--set", "model.storage=fp16"},
                           "--set model.storage: changes the simulation state (the precision");
  test::expectOneLineError({"render", "swarm-orbit", "--resume", ckpt, "--out", out, "--set", "particles=1000"},
                           "--set particles: changes the simulation state (the particle count)");
  test::expectOneLineError({"render", "ripples", "--resume", ckpt, "--out", out, "--set", "width=64"},
                           "--set width: changes the simulation state (the grid's size)");
  test::expectOneLineError({"run", scene, "--backend", "egl", "--resume", ckpt, "--set", "particles.jitter=0"},
                           "--set particles.jitter: changes the simulation state");
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(ResumeSetCli, BadValuesNameTheirSetNotTheSceneFile) {
  test::TempDir dir;
  dir.write("dam.json", kSmallDam);
  const std::string scene = (dir / "dam.json").string(), out = (dir / "f").string();
  const struct {
    const char *set, *expected;
  } cases[] = {
      {"view.mode=bogus", "--set 'view.mode=bogus': params.view.mode = 'bogus' is not one of: balls, water"},
      {"particles.resolution=abc", "--set 'particles.resolution=abc': params.particles.resolution: expected a number"},
      {"engine.substeps=0", "--set 'engine.substeps=0': params.engine.substeps = 0 is out of range [1, 1000]"},
      {"view.show_box=3", "--set 'view.show_box=3': params.view.show_box: expected true or false, got 3"},
      {"view.mode=\x1b[31m", "--set 'view.mode=\\x1b[31m': params.view.mode = '\\x1b[31m' is not one of"},
  };
  for (const auto& c : cases) {
    const auto r = test::expectOneLineError({"render", scene, "--set", c.set, "--out", out}, c.expected);
    EXPECT_EQ(r.err.find("dam.json"), std::string::npos) << r.err;
  }
  // The file's own fault still names the file, whatever --set says.
  dir.write("bad.json", R"({"model": "balls", "params": {"engine": {"dt": -1}}})");
  const auto r = test::expectOneLineError(
      {"render", (dir / "bad.json").string(), "--set", "view.mode=water", "--out", out}, "bad.json: params.engine.dt");
  EXPECT_EQ(r.err.find("--set"), std::string::npos) << r.err;
}

TEST(ResumeSetCli, StaleFramesAfterTheLastWrittenAreReported) {
  test::TempDir dir;
  dir.write("dam.json", kSmallDam);
  const std::string scene = (dir / "dam.json").string(), out = (dir / "f").string();
  for (int i = 0; i < 120; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "f/frame_%05d.png", i);
    dir.write(name, "");
  }
  dir.write("f/notes.txt", "");
  auto r = render({scene, "--frames", "3", "--out", out, "--checkpoint", (dir / "c.ckpt").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("warning: " + out +
                       " holds 117 older frames beyond frame_00002.png (frame_00003.png to frame_00119.png) from "
                       "an earlier run; delete them or use a new --out"),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "f/frame_00119.png"));  // nothing deleted
  // Resumed: frames 3 and 4 follow the checkpoint's; the ones before are the clip's, not stale.
  for (int i = 5; i < 120; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", i);
    std::filesystem::remove(dir / "f" / name);
  }
  r = render({scene, "--resume", (dir / "c.ckpt").string(), "--frames", "2", "--out", out});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  dir.write("f/frame_00007.png", "");
  r = render({scene, "--resume", (dir / "c.ckpt").string(), "--frames", "2", "--out", out});
  EXPECT_NE(r.err.find("holds 1 older frame beyond frame_00004.png (frame_00007.png) from an earlier run"),
            std::string::npos)
      << r.err;
}
