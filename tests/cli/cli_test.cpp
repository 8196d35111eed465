// The executable end to end: info, headless render (PNG frames with the scene's colour), run
// without a display, the OSMesa fallback, and the README's quick-start path.
#include <gtest/gtest.h>

#include "io/png.h"
#include "support/gl_test.h"
#include "support/one_line_error.h"
#include "support/run_process.h"

using namespace tidepool;
using test::runTidepool;

TEST(Cli, InfoReportsGl43OrNewerAndComputeLimits) {
  auto r = runTidepool({"info", "--backend", "egl"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("GL_RENDERER"), std::string::npos);
  EXPECT_NE(r.out.find("compute work-group size"), std::string::npos);
  EXPECT_NE(r.out.find("compute self-test         ok"), std::string::npos) << r.out;
  const std::size_t at = r.out.find("context version");
  ASSERT_NE(at, std::string::npos);
  const int major = std::stoi(r.out.substr(at + 26, 1)), minor = std::stoi(r.out.substr(at + 28, 1));
  EXPECT_TRUE(major > 4 || (major == 4 && minor >= 3)) << r.out;
}

TEST(Cli, OsMesaFallbackCreatesAGl43Context) {
  auto r = runTidepool({"info", "--backend", "osmesa"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("backend                   osmesa"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("compute self-test         ok"), std::string::npos) << r.out;
}

TEST(Cli, RenderWritesFramesOfTheRequestedSizeAndColour) {
  test::TempDir dir;
  dir.write("red.json", R"({"model": "blank", "params": {"color": [1, 0, 0]}, "clip": {"frames": 7}})");
  auto r = runTidepool({"render", (dir / "red.json").string(), "--frames", "3", "--size", "48x20", "--out",
                        (dir / "frames").string(), "--quiet"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("wrote 3 frames (48x20)"), std::string::npos) << r.err;
  for (int i = 0; i < 3; ++i) {
    io::Image img = io::readPng(dir / ("frames/frame_0000" + std::to_string(i) + ".png"));
    EXPECT_EQ(img.width, 48);
    EXPECT_EQ(img.height, 20);
    EXPECT_EQ(img.rgba[0], 255);
    EXPECT_EQ(img.rgba[1], 0);
    EXPECT_EQ(img.rgba[2], 0);
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "frames/frame_00003.png"));
}

TEST(Cli, RunWithoutADisplayRendersTheClipHeadlessAndSaysWhere) {
  test::TempDir dir;
  auto r =
      runTidepool({"run", "default", "--frames", "2", "--out", dir.path().string()}, {"DISPLAY=", "WAYLAND_DISPLAY="});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("no display"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(dir.path().string() + "/default/frame_*.png"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "default/frame_00001.png"));
}

// Without a display, run's --size is the clip's size when given, and the scene's clip size when not
// (its window default, 1280x720, is for windows).
TEST(Cli, RunWithoutADisplayRendersAtSizeOrTheScenesClipSize) {
  test::TempDir dir;
  dir.write("red.json", R"({"model": "blank", "clip": {"width": 24, "height": 10}})");
  const std::vector<std::string> noDisplay = {"DISPLAY=", "WAYLAND_DISPLAY="};
  auto r = runTidepool(
      {"run", (dir / "red.json").string(), "--frames", "1", "--size", "16x8", "--out", (dir / "sized").string()},
      noDisplay);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  io::Image img = io::readPng(dir / "sized/red/frame_00000.png");
  EXPECT_EQ(img.width, 16);
  EXPECT_EQ(img.height, 8);
  r = runTidepool({"run", (dir / "red.json").string(), "--frames", "1", "--out", (dir / "clip").string()}, noDisplay);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  img = io::readPng(dir / "clip/red/frame_00000.png");
  EXPECT_EQ(img.width, 24);
  EXPECT_EQ(img.height, 10);
}

// With neither --out nor --video, render writes where run does without a display: out/<scene>
// in the working folder, and says so.
TEST(Cli, RenderWithoutOutOrVideoWritesToOutSceneHere) {
  test::TempDir dir;
  dir.write("red.json", R"({"model": "blank", "params": {"color": [1, 0, 0]}})");
  const auto r = test::runProcess(
      {"sh", "-c",
       "cd '" + dir.path().string() + "' && exec '" TIDEPOOL_EXE "' render red.json --frames 2 --size 16x8 --quiet"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("no --out or --video: writing to out/red"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(dir.path().string() + "/out/red/frame_*.png"), std::string::npos) << r.err;
  EXPECT_EQ(io::readPng(dir / "out/red/frame_00001.png").width, 16);
}

TEST(Cli, VideoWithoutFfmpegIsAClearError) {
  test::TempDir dir;
  test::expectOneLineError({"render", "blank", "--frames", "2", "--video", (dir / "c.mp4").string()},
                           "--video needs ffmpeg", 1, {"PATH=/nonexistent"});
}

TEST(Cli, HelpAndVersionSucceed) {
  EXPECT_EQ(runTidepool({"--help"}).exitCode, 0);
  EXPECT_EQ(runTidepool({"render", "--help"}).exitCode, 0);
  auto v = runTidepool({"--version"});
  EXPECT_EQ(v.exitCode, 0);
  EXPECT_NE(v.out.find("tidepool"), std::string::npos);
}

TEST(Cli, VideoFramesArePipedToFfmpeg) {
  // A stand-in ffmpeg on PATH that stores the raw RGBA stream in the output file.
  test::TempDir dir;
  dir.write("bin/ffmpeg", "#!/bin/sh\nfor last; do :; done\ncat > \"$last\"\n");
  std::filesystem::permissions(dir / "bin/ffmpeg", std::filesystem::perms::owner_all);
  const std::string path = std::string(std::getenv("PATH"));
  auto r = runTidepool(
      {"render", "blank", "--frames", "4", "--size", "30x10", "--video", (dir / "c.mp4").string(), "--quiet"},
      {"PATH=" + (dir / "bin").string() + ":" + path});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(std::filesystem::file_size(dir / "c.mp4"), 4u * 30 * 10 * 4) << "4 raw RGBA frames";
  EXPECT_NE(r.err.find("wrote video"), std::string::npos) << r.err;
}
