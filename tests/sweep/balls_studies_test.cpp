// The balls-settle and balls-dambreak studies, quick runs on llvmpipe: rows land in the CSV (and
// redraw from it, the GPU machine's path), and the measured errors behave as the methods predict.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "io/png.h"
#include "support/gl_test.h"
#include "support/run_process.h"
#include "support/sweep_column.h"
#include "sweep/sweep.h"

using namespace tidepool;

namespace {

// Runs a quick study with --no-chart, redraws it with --from-csv and returns its rows.
sweep::Result quickStudy(const test::TempDir& dir, const std::string& study) {
  auto run = test::runTidepool({"sweep", study, "--quick", "--no-chart", "--csv-dir", dir.path().string()});
  EXPECT_EQ(run.exitCode, 0) << run.out << run.err;
  auto redraw = test::runTidepool(
      {"sweep", study, "--from-csv", "--csv-dir", dir.path().string(), "--chart-dir", dir.path().string()});
  EXPECT_EQ(redraw.exitCode, 0) << redraw.out << redraw.err;
  EXPECT_EQ(io::readPng(dir / (study + ".png")).width, 1000);
  std::string device;
  return sweep::readResult(dir / (study + ".csv"), dir / (study + ".chart.json"), device);
}

// Rows of one method by dt.
std::map<double, const sweep::Row*> byDt(const sweep::Result& r, const std::string& method) {
  std::map<double, const sweep::Row*> out;
  for (const sweep::Row& row : r.rows)
    if (row.method == method) out[row.dt] = &row;
  return out;
}

}  // namespace

// A touching cubic stack under gravity: the penalty law's overlap grows as dt (its stiffness is
// 0.48/dt), the spring-dashpot's at t_c = 20 dt as dt²; the block sinks, so its energy falls.
TEST(BallsStudies, SettleOverlapFallsWithDtAtEachLawsOrder) {
  test::TempDir dir;
  const sweep::Result r = quickStudy(dir, "balls-settle");
  ASSERT_EQ(r.rows.size(), 7u);
  const std::size_t overlap = test::metricColumn(r, "max_overlap_r"), drift = test::metricColumn(r, "energy_drift");
  const std::map<std::string, std::pair<double, double>> orders = {
      {"penalty, symplectic-euler", {1.6, 2.5}},
      {"spring-dashpot tc = 20 dt, symplectic-euler", {3.2, 5.0}},
      {"spring-dashpot tc = 20 dt, verlet", {3.2, 5.0}}};
  for (const auto& [method, band] : orders) {
    SCOPED_TRACE(method);
    const auto rows = byDt(r, method);
    ASSERT_GE(rows.size(), 2u);
    for (auto fine = rows.begin(), coarse = std::next(fine); coarse != rows.end(); ++fine, ++coarse) {
      ASSERT_TRUE(fine->second->stable && coarse->second->stable);
      EXPECT_NEAR(coarse->first, 2 * fine->first, 1e-12);
      const double ratio = coarse->second->metrics[overlap] / fine->second->metrics[overlap];
      EXPECT_GT(ratio, band.first) << "dt " << coarse->first << " against " << fine->first;
      EXPECT_LT(ratio, band.second);
      EXPECT_LT(coarse->second->metrics[drift], fine->second->metrics[drift]) << "a stiffer block sinks less";
      EXPECT_LT(fine->second->metrics[drift], 0.0);
    }
  }
}

// The surge front converges to the finest-dt reference: over the deterministic first half
// (T* <= 1.2) the coarsest run deviates most and the rerun at the reference's own dt least.
TEST(BallsStudies, DambreakFrontConvergesToTheFinestDtReference) {
  test::TempDir dir;
  const sweep::Result r = quickStudy(dir, "balls-dambreak");
  ASSERT_EQ(r.rows.size(), 7u);
  const std::size_t early = test::metricColumn(r, "rms_deviation_early"), full = test::metricColumn(r, "rms_deviation");
  const auto rows = byDt(r, "symplectic-euler");  // the scene's own method, t_c/dt 20, 10, 5
  const auto reruns = byDt(r, "reference rerun (run-to-run spread)");
  ASSERT_EQ(rows.size(), 3u);
  ASSERT_EQ(reruns.size(), 1u);
  for (const sweep::Row& row : r.rows) {
    EXPECT_TRUE(row.stable) << row.method << " " << row.dt;
    EXPECT_TRUE(std::isfinite(row.metrics[full]));
  }
  const double rerun = reruns.begin()->second->metrics[early];
  const double fine = rows.begin()->second->metrics[early];
  const double coarsest = rows.rbegin()->second->metrics[early];
  EXPECT_LT(rerun, 0.25 * fine) << "the rerun at the reference dt is the floor";
  EXPECT_GT(coarsest, 1.5 * fine) << "t_c/dt = 5 deviates more than t_c/dt = 20";
}
