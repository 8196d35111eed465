// Benchmark tables a reader can trust: a GPU-timer column whose queries read nothing shows '-'
// (explained under the table), a column that holds a sum is never below its part, and each row
// is announced on stderr as it starts, so that stdout keeps only the table. Timings are never
// asserted: only which cells are measured and how the columns relate within a row.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "bench/bench.h"
#include "support/gl_test.h"
#include "support/run_process.h"

using namespace tidepool;
using test::runTidepool;

namespace {

// The CSV's rows as cells, the header first.
std::vector<std::vector<std::string>> readCsv(const std::filesystem::path& path) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> row;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) row.push_back(cell);
    rows.push_back(row);
  }
  return rows;
}

std::size_t column(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t c = 0; c < header.size(); ++c)
    if (header[c] == name) return c;
  ADD_FAILURE() << "no column '" << name << "'";
  return 0;
}

bool software(const test::ProcessResult& r) { return r.out.find("is a software renderer") != std::string::npos; }

}  // namespace

TEST(BenchColumns, PassTimersThatReadNothingShowADash) {
  bench::PassTimes zero;
  zero.passes["balls.count"] = {0.0, 1e-6, 0.0};  // llvmpipe: 0 or 1 ns
  EXPECT_FALSE(zero.timersRead());
  EXPECT_EQ(zero.cell("balls.count", 4), bench::kNotMeasured);
  bench::PassTimes real;
  real.passes["balls.count"] = {0.25, 0.5, 0.75};
  EXPECT_TRUE(real.timersRead());
  EXPECT_EQ(real.cell("balls.count", 4), "0.5000");
  EXPECT_EQ(real.cell("balls.obstacles", 4), "-");  // a pass that never ran
  real.software = true;
  EXPECT_EQ(real.cell("balls.count", 4), bench::kNotMeasured);
  const std::string note = bench::timingCaveat("llvmpipe (LLVM 15.0.6, 256 bits)");
  EXPECT_NE(note.find("timer queries read 0"), std::string::npos) << note;
  EXPECT_NE(note.find(std::string("show '") + bench::kNotMeasured + "'"), std::string::npos) << note;
  EXPECT_EQ(bench::timingCaveat("NVIDIA H100 80GB HBM3/PCIe/SSE2"), "");
}

TEST(BenchColumns, BallsRowsAreAnnouncedOnStderrAndUnmeasuredPassesShowADash) {
  test::TempDir dir;
  const auto r = runTidepool({"bench", "balls", "--n", "4096", "--steps", "2:4", "--deterministic", "on,off", "--csv",
                              (dir / "b.csv").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("bench balls 1/2: about 4096 balls, determ. on"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("bench balls 2/2: about 4096 balls, determ. off"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("bench balls: 2 rows in "), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("bench balls 1/2"), std::string::npos) << r.out;  // stdout: the table alone
  const auto rows = readCsv(dir / "b.csv");
  ASSERT_EQ(rows.size(), 3u);
  for (const char* pass : {"count ms", "scan ms", "collide ms"}) {
    const std::string cell = rows[1][column(rows[0], pass)];
    if (software(r))
      EXPECT_EQ(cell, bench::kNotMeasured) << pass;
    else
      EXPECT_NE(cell, bench::kNotMeasured) << pass;
  }
}

TEST(BenchColumns, FramePlusExportIsNeverBelowTheFrame) {
  test::TempDir dir;
  const auto r = runTidepool({"bench", "export", "dam-break", "--frames", "3", "--warmup", "0", "--format", "vtk,ply",
                              "--csv", (dir / "e.csv").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("bench export 2/2: ply, 3 frames"), std::string::npos) << r.err;
  const auto rows = readCsv(dir / "e.csv");
  ASSERT_EQ(rows.size(), 3u);
  for (std::size_t k = 1; k < rows.size(); ++k)  // the same frames on the same clock: a sum and its part
    EXPECT_GE(std::stod(rows[k][column(rows[0], "frame+export ms")]), std::stod(rows[k][column(rows[0], "frame ms")]));
}

TEST(BenchColumns, SurfaceGpuColumnsShowADashWhereTimersReadNothing) {
  test::TempDir dir;
  const auto r = runTidepool({"bench", "surface", "--particles", "4000", "--resolution", "16,24", "--steps", "1",
                              "--repeats", "2", "--warmup", "0", "--csv", (dir / "s.csv").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("bench surface 2/2: resolution 24"), std::string::npos) << r.err;
  const auto rows = readCsv(dir / "s.csv");
  ASSERT_EQ(rows.size(), 3u);
  if (!software(r)) GTEST_SKIP() << "timer queries measure on this driver";
  for (const char* name : {"splat ms", "emit ms", "GPU ms"}) EXPECT_EQ(rows[1][column(rows[0], name)], "-") << name;
  EXPECT_NE(rows[1][column(rows[0], "build ms")], "-");
}
