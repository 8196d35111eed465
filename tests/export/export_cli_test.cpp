// `tidepool render --export` end to end on bad input: each refusal is one line naming the option,
// the file or the folder, with a non-zero exit and no crash; a write that fails midway (a file
// size limit) ends the run naming the file, with no half-written frame left behind.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include "support/gl_test.h"
#include "support/one_line_error.h"

using namespace tidepool;

namespace {

const std::string kBalls = std::string(TIDEPOOL_TEST_DATA) + "/soak/balls.json";  // 363 balls
const std::string kRipples = std::string(TIDEPOOL_TEST_DATA) + "/soak/ripples.json";

}  // namespace

TEST(ExportCli, OutUnderARegularFileIsOneLine) {
  test::TempDir dir;
  dir.write("file", "x");
  test::expectOneLineError({"render", kBalls, "--frames", "2", "--size", "32x18", "--export", "vtk", "--out",
                            (dir / "file/out").string(), "--quiet"},
                           "cannot create output folder '" + (dir / "file/out").string() + "': Not a directory");
}

TEST(ExportCli, UnknownFormatEveryZeroAndEveryAloneAreOneLine) {
  test::TempDir dir;
  const std::string out = (dir / "out").string();
  test::expectOneLineError({"render", kBalls, "--frames", "2", "--export", "xyz", "--out", out, "--quiet"},
                           "--export 'xyz' is not a format (expected vtk, ply or surface)");
  test::expectOneLineError(
      {"render", kBalls, "--frames", "2", "--export", "ply", "--every", "0", "--out", out, "--quiet"},
      "--every 0 must be at least 1");
  test::expectOneLineError({"render", kBalls, "--frames", "2", "--every", "2", "--out", out, "--quiet"},
                           "--every requires --export", 2);
  test::expectOneLineError({"render", kBalls, "--frames", "2", "--export", "vtk", "--video", out + ".mp4", "--quiet"},
                           "--export needs --out DIR");
}

TEST(ExportCli, RipplesIsVtkOnlyAndBlankHasNothingToExport) {
  test::TempDir dir;
  test::expectOneLineError(
      {"render", kRipples, "--frames", "2", "--export", "ply", "--out", (dir / "out").string(), "--quiet"},
      "ripples has no particles: --export ply needs balls, fluid, life or swarm (--export vtk writes its heightfield)");
  test::expectOneLineError(
      {"render", "blank", "--frames", "2", "--export", "vtk", "--out", (dir / "out").string(), "--quiet"},
      "blank has no particles: --export vtk|ply needs balls, fluid, life or swarm");
}

TEST(ExportCli, AFailingWriteNamesTheFileAndLeavesNoPartialFrame) {
  test::TempDir dir;
  const std::filesystem::path out = dir / "out";
  // A frame of 363 balls is 14 KB; the limit (in 512-byte blocks for sh) stops the first one.
  // SIGXFSZ is ignored so that the write returns EFBIG, as on a full disk, instead of killing.
  const std::string command = "ulimit -f 8; trap '' XFSZ; exec '" + std::string(TIDEPOOL_EXE) + "' render '" + kBalls +
                              "' --frames 4 --size 32x18 --export vtk --no-frames --quiet --out '" + out.string() + "'";
  const test::ProcessResult r = test::runProcess({"sh", "-c", command});
  EXPECT_FALSE(r.signaled) << r.err;
  EXPECT_EQ(r.exitCode, 1) << r.err;
  const std::vector<std::string> lines = r.errLines();
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_NE(lines[0].find("cannot write '" + (out / "frame_00000.vtp").string() + "': File too large"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(out / "frame_00000.vtp"));
  EXPECT_FALSE(std::filesystem::exists(out / "frame_00000.vtp.tmp"));
}

TEST(ExportCli, BenchExportTimesBothFormats) {
  auto r = test::runTidepool({"bench", "export", kBalls, "--repeats", "2", "--warmup", "0"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("363 points"), std::string::npos) << r.out;
  for (const char* row : {R"(\n +363 +vtk +[0-9])", R"(\n +363 +ply +[0-9])"})
    EXPECT_TRUE(std::regex_search(r.out, std::regex(row))) << row << "\n" << r.out;
  test::expectOneLineError({"bench", "export", kBalls, "--format", "obj"}, "--format 'obj' is not vtk or ply");
  test::expectOneLineError({"bench", "export", kRipples, "--format", "ply"}, "ripples has no particles");
}

// The scene's probes go beside the exported frames, one row per exported frame in probes.csv with
// validate's columns; a probe the model cannot measure (a pressure on the balls) is one line before
// any frame.
TEST(ExportCli, ProbesAreWrittenBesideTheFramesOrRefusedInOneLine) {
  test::TempDir dir;
  const std::filesystem::path out = dir / "out";
  auto r = test::runTidepool({"render", "fluid-tank", "--frames", "3", "--size", "32x18", "--export", "vtk", "--every",
                              "2", "--no-frames", "--quiet", "--out", out.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::ifstream csv(out / "probes.csv");
  std::vector<std::string> lines;
  for (std::string line; std::getline(csv, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 3u) << "a header and frames 0 and 2";
  EXPECT_EQ(lines[0],
            "time_s,frame,gauge0_height_m,gauge1_height_m,gauge2_height_m,pressure3_pa,pressure4_pa,force5_normal_n,"
            "force6_normal_n");
  EXPECT_EQ(lines[1].substr(0, 4), "0,0,") << "frame 0 at t = 0: " << lines[1];
  EXPECT_EQ(lines[2].find("nan"), std::string::npos) << "frame 2 has stepped: every probe measured: " << lines[2];

  dir.write("balls.json", R"({"model": "balls", "params": {"particles": {"radius": 0.01,
      "domain_max": [0.2, 0.1, 0.2], "fill": "slab", "slab_height": 0.05},
      "probes": [{"kind": "pressure", "at": [0.1, 0.05, 0.02]}]}})");
  test::expectOneLineError({"render", (dir / "balls.json").string(), "--frames", "2", "--size", "32x18", "--export",
                            "vtk", "--out", (dir / "balls").string(), "--quiet"},
                           "balls: a pressure probe reads the fluid solver's pressure");
  EXPECT_FALSE(std::filesystem::exists(dir / "balls" / "frame_00000.vtp"));
}
