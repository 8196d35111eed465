// Benchmarks run end to end at tiny sizes (timings are never asserted) and reject bad sizes.
#include <gtest/gtest.h>

#include "support/gl_test.h"
#include "support/run_process.h"

using namespace tidepool;
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
  auto r = runTidepool({"bench", "ripples", "--size", "12x"});
  EXPECT_EQ(r.exitCode, 1);
  ASSERT_EQ(r.errLines().size(), 1u) << r.err;
  EXPECT_NE(r.err.find("size '12x' is not a number"), std::string::npos) << r.err;
  auto big = runTidepool({"bench", "ripples", "--size", "16384"});
  EXPECT_EQ(big.exitCode, 1);
  EXPECT_FALSE(big.signaled);
  EXPECT_NE(big.err.find("storage-buffer limit"), std::string::npos) << big.err;
}
