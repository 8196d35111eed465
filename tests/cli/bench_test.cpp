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
                             "caustics ms", "compose ms", "frame ms"})
    EXPECT_NE(r.out.find(column), std::string::npos) << column << "\n" << r.out;
  const std::string csv = io::readTextFile(dir / "render.csv");
  for (const char* row :
       {",balls,clear,compute,", ",water,clear,compute,", ",balls,clear,fragment,", ",water,clear,fragment,"})
    EXPECT_NE(csv.find(row), std::string::npos) << row << "\n" << csv;
  expectOneLineError({"bench", "render", "--size", "1920"}, "--size '1920' is not WIDTHxHEIGHT");
  expectOneLineError({"bench", "render", "--raster", "rops"}, "--raster 'rops' is not compute, fragment or both");
  expectOneLineError({"bench", "render", "--look", "seed,murky"}, "--look 'murky' is not one of: seed, clear, ocean");
}

// --look: a row per look and mode.
TEST(Bench, RenderRowsForEachLook) {
  test::TempDir dir;
  auto r = runTidepool({"bench", "render", "--n", "4096", "--size", "96x54", "--settle", "2", "--repeats", "1",
                        "--raster", "compute", "--look", "seed,clear,ocean", "--csv", (dir / "render.csv").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string csv = io::readTextFile(dir / "render.csv");
  for (const char* row : {",water,seed,compute,", ",water,clear,compute,", ",water,ocean,compute,"})
    EXPECT_NE(csv.find(row), std::string::npos) << row << "\n" << csv;
}

TEST(Bench, GridGivesACheckedRowPerSizeAndLoad) {
  test::TempDir dir;
  auto r = runTidepool({"bench", "grid", "--n", "4096,5000", "--ppc", "4", "--repeats", "2", "--warmup", "0", "--csv",
                        (dir / "grid.csv").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string csv = io::readTextFile(dir / "grid.csv");
  EXPECT_EQ(csv.rfind("N,cells,ppc,count_ms,", 0), 0u) << csv;
  for (const char* n : {"\n4096,", "\n5000,"}) {
    const std::size_t at = csv.find(n);
    ASSERT_NE(at, std::string::npos) << n << "\n" << csv;
    EXPECT_NE(csv.substr(at + 1, csv.find('\n', at + 1) - at - 1).find(",checked"), std::string::npos) << csv;
  }
  expectOneLineError({"bench", "grid", "--n", "4096", "--ppc", "-1"}, "--ppc '-1' is not a positive number");
}

TEST(Bench, BallsRunsEachSizeInEachGridOrder) {
  test::TempDir dir;
  auto r = runTidepool({"bench", "balls", "bench-lattice", "--n", "4096,8192", "--steps", "1:3", "--deterministic",
                        "on,off", "--csv", (dir / "balls.csv").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string csv = io::readTextFile(dir / "balls.csv");
  EXPECT_NE(csv.find("mean ms"), std::string::npos) << csv;
  for (const char* row : {"4096,", "8192,", ",on,", ",off,"})
    EXPECT_NE(csv.find(row), std::string::npos) << row << "\n" << csv;
  std::size_t rows = 0;
  for (char c : csv) rows += c == '\n';
  EXPECT_EQ(rows, 5u) << csv;  // the header, each size in each order
  expectOneLineError({"bench", "balls", "bench-lattice", "--n", "4096", "--deterministic", "maybe"},
                     "--deterministic 'maybe' is not");
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

// --bodies adds that many boxes afloat, dynamic and (with --dynamic off) held: one row each, and
// a single row for none.
TEST(Bench, FluidRowsForBodiesDynamicAndHeld) {
  test::TempDir dir;
  auto r = runTidepool({"bench", "fluid", "bench-fluid", "--n", "4096", "--bodies", "0,2", "--dynamic", "off,on",
                        "--steps", "1:3", "--repeats", "1", "--csv", (dir / "fluid.csv").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string csv = io::readTextFile(dir / "fluid.csv");
  EXPECT_NE(csv.find(",0,off,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",2,off,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",2,on,"), std::string::npos) << csv;
  std::size_t rows = 0;
  for (char c : csv) rows += c == '\n';
  EXPECT_EQ(rows, 4u) << csv;
  expectOneLineError({"bench", "fluid", "bench-fluid", "--bodies", "17"},
                     "--bodies '17' is not a whole number in [0, 16]");
}
