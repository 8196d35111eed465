// Benchmarks run end to end at tiny sizes (timings are never asserted) and reject bad sizes.
#include <gtest/gtest.h>

#include <sstream>

#include "io/json.h"
#include "support/gl_test.h"
#include "support/one_line_error.h"

using namespace tidepool;
using test::expectOneLineError;
using test::runTidepool;

TEST(Bench, RipplesPrintsItsTableAndCsv) {
  test::TempDir dir;
  auto r = runTidepool(
      {"bench", "ripples", "--size", "32,64", "--repeats", "2", "--warmup", "0", "--csv", (dir / "r.csv").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("ms/step"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("64^2"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir / "r.csv"));
}

TEST(Bench, BadSizeIsAOneLineError) {
  expectOneLineError({"bench", "ripples", "--size", "12x"}, "size '12x' is not a number");
  auto big = runTidepool({"bench", "ripples", "--size", "16384"});
  EXPECT_EQ(big.exitCode, 1);
  EXPECT_FALSE(big.signaled);
  EXPECT_NE(big.err.find("storage-buffer limit"), std::string::npos) << big.err;
}

TEST(Bench, RenderPrintsMsPerPassInBothModes) {
  test::TempDir dir;
  auto r = runTidepool({"bench", "render", "--n", "4096", "--size", "96x54", "--settle", "2", "--repeats", "2",
                        "--warmup", "1", "--csv", (dir / "render.csv").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* column : {"scene ms", "gbuffer ms", "thickness ms", "splat ms", "id ms", "resolve ms", "blur ms",
                             "compose ms", "frame ms"})
    EXPECT_NE(r.out.find(column), std::string::npos) << column << "\n" << r.out;
  const std::string csv = io::readTextFile(dir / "render.csv");
  for (const char* row : {",balls,compute,", ",water,compute,", ",balls,fragment,", ",water,fragment,"})
    EXPECT_NE(csv.find(row), std::string::npos) << row << "\n" << csv;
  expectOneLineError({"bench", "render", "--size", "1920"}, "--size '1920' is not WIDTHxHEIGHT");
  expectOneLineError({"bench", "render", "--raster", "rops"}, "--raster 'rops' is not compute, fragment or both");
}

TEST(Bench, GridGivesOneCheckedRowPerReorderMode) {
  test::TempDir dir;
  auto r = runTidepool({"bench", "grid", "--n", "4096", "--ppc", "4", "--reorder", "scatter,gather", "--repeats", "2",
                        "--warmup", "0", "--csv", (dir / "grid.csv").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string csv = io::readTextFile(dir / "grid.csv");
  EXPECT_EQ(csv.rfind("N,cells,ppc,reorder,count_ms,", 0), 0u) << csv;
  for (const char* mode : {",scatter,", ",gather,"}) {
    const std::size_t at = csv.find(mode);
    ASSERT_NE(at, std::string::npos) << mode << "\n" << csv;
    EXPECT_NE(csv.substr(at, csv.find('\n', at) - at).find(",checked"), std::string::npos) << csv;
  }
  expectOneLineError({"bench", "grid", "--n", "4096", "--reorder", "scatter,sideways"},
                     "--reorder 'sideways' is not scatter or gather");
}

// The by-shape scan table names each shape with its fuse suffix and its dispatch count.
TEST(Bench, GridScanShapesCompareFusedAndScannedOffsets) {
  auto r = runTidepool({"bench", "grid", "--n", "65536", "--ppc", "4", "--scan-shapes", "256x4f0,256x4f8,256x4,256x4p",
                        "--repeats", "2", "--warmup", "0"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out.find("WRONG"), std::string::npos) << r.out;
  auto dispatchesOf = [&](const std::string& shape) {  // row "N shape dispatches ..." of the by-shape table
    std::istringstream lines(r.out);
    for (std::string line; std::getline(lines, line);) {
      std::istringstream words(line);
      std::string n, name, dispatches;
      if (words >> n >> name >> dispatches && n == "65536" && name == shape) return dispatches;
    }
    return std::string("no row");
  };
  EXPECT_EQ(dispatchesOf("256x4f0"), "3") << r.out;  // 16 blocks: reduce, top, scan
  EXPECT_EQ(dispatchesOf("256x4f8"), "3") << r.out;  // 16 blocks: more than it fuses
  EXPECT_EQ(dispatchesOf("256x4"), "2") << r.out;    // the default fuses them
  EXPECT_EQ(dispatchesOf("256x4p"), "3") << r.out;
  for (const char* shape : {"256x4q", "256x4f", "256x4f1x", "x4"})
    expectOneLineError({"bench", "grid", "--n", "4096", "--scan-shapes", shape},
                       "--scan-shapes '" + std::string(shape) + "' is not like");
}

TEST(Bench, BallsRunsEachSizeInEachReorderMode) {
  test::TempDir dir;
  auto r = runTidepool({"bench", "balls", "bench-lattice", "--n", "4096", "--steps", "1:3", "--reorder",
                        "scatter,gather", "--csv", (dir / "balls.csv").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string csv = io::readTextFile(dir / "balls.csv");
  for (const char* mode : {",scatter,", ",gather,"})
    EXPECT_NE(csv.find(mode), std::string::npos) << mode << "\n" << csv;
  expectOneLineError({"bench", "balls", "bench-lattice", "--n", "4096", "--reorder", "scatterr"},
                     "--reorder 'scatterr' is not scatter or gather");
}

TEST(Bench, BallsClocksThePassesEachWay) {
  test::TempDir dir;
  auto r = runTidepool({"bench", "balls", "bench-lattice", "--n", "4096", "--steps", "1:3", "--timers",
                        "queued,isolated,off", "--csv", (dir / "balls.csv").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string csv = io::readTextFile(dir / "balls.csv");
  EXPECT_NE(csv.find("mean ms"), std::string::npos) << csv;
  for (const char* row : {",queued,", ",isolated,", ",off,"})
    EXPECT_NE(csv.find(row), std::string::npos) << row << "\n" << csv;
  expectOneLineError({"bench", "balls", "bench-lattice", "--n", "4096", "--timers", "queued,never"},
                     "--timers 'never' is not");
}

TEST(Bench, BallsRunsTheGridAndVerletListsAtEachSkin) {
  test::TempDir dir;
  auto r = runTidepool({"bench", "balls", "bench-lattice", "--n", "4096", "--steps", "1:4", "--neighbours",
                        "grid,lists", "--skin", "0.2,0.5", "--csv", (dir / "balls.csv").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string csv = io::readTextFile(dir / "balls.csv");
  for (const char* row : {",grid,", ",lists 0.20,", ",lists 0.50,"})
    EXPECT_NE(csv.find(row), std::string::npos) << row << "\n" << csv;
  std::size_t rows = 0;
  for (char c : csv) rows += c == '\n';
  EXPECT_EQ(rows, 4u) << csv;  // the header, the grid once, lists once per skin
  expectOneLineError({"bench", "balls", "bench-lattice", "--n", "4096", "--neighbours", "grid,cells"},
                     "--neighbours 'cells' is not grid or lists");
  expectOneLineError({"bench", "balls", "bench-lattice", "--n", "4096", "--neighbours", "lists", "--skin", "9"},
                     "--skin '9' is not a fraction of r in [0.01, 4]");
}

TEST(Bench, FluidRunsEachSizeAndIterationCount) {
  test::TempDir dir;
  auto r = runTidepool({"bench", "fluid", "bench-fluid", "--n", "4096", "--iterations", "1,4", "--steps", "1:3",
                        "--repeats", "1", "--csv", (dir / "fluid.csv").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string csv = io::readTextFile(dir / "fluid.csv");
  EXPECT_NE(csv.find("bytes/particle"), std::string::npos) << csv;
  std::size_t rows = 0;
  for (char c : csv) rows += c == '\n';
  EXPECT_EQ(rows, 3u) << csv;  // the header and one row per iteration count
  expectOneLineError({"bench", "fluid", "bench-fluid", "--n", "4096", "--iterations", "0"},
                     "--iterations '0' is not a whole number in [1, 100]");
}
