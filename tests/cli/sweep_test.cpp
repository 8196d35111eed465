// Sweeps write their CSV rows and draw charts; the Pareto front is the set nothing dominates.
#include <gtest/gtest.h>

#include <fstream>

#include "io/png.h"
#include "support/gl_test.h"
#include "support/run_process.h"
#include "sweep/sweep.h"

using namespace tidepool;

TEST(Sweep, ParetoFrontKeepsOnlyUndominatedStableRows) {
  std::vector<sweep::Row> rows(5);
  const double xy[5][2] = {{1, 10}, {2, 5}, {3, 6}, {4, 1}, {0.5, 0.5}};
  for (int i = 0; i < 5; ++i) {
    rows[i].x = xy[i][0];
    rows[i].y = xy[i][1];
  }
  rows[4].stable = false;  // cheapest and best, but it blew up: it dominates nothing
  sweep::markPareto(rows);
  EXPECT_TRUE(rows[0].pareto);
  EXPECT_TRUE(rows[1].pareto);
  EXPECT_FALSE(rows[2].pareto) << "(3, 6) is dominated by (2, 5)";
  EXPECT_TRUE(rows[3].pareto);
  EXPECT_FALSE(rows[4].pareto);
}

TEST(Sweep, StudiesWriteCsvAndCharts) {
  test::TempDir dir;
  for (const std::string study :
       {"ripples-stability", "ripples-dispersion", "balls-restitution", "swarm-orbit", "swarm-precision",
        "life-precision", "swarm-stability", "life-stability", "balls-stability"}) {
    auto r = test::runTidepool(
        {"sweep", study, "--quick", "--csv-dir", dir.path().string(), "--chart-dir", dir.path().string()});
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    std::ifstream csv(dir / (study + ".csv"));
    std::string header, line;
    std::getline(csv, header);
    EXPECT_EQ(header.rfind("study,model,method,dt,substeps,resolution,gpu_ms_per_sim_s,", 0), 0u) << header;
    EXPECT_NE(header.find(",stable,pareto,device"), std::string::npos);
    int rows = 0;
    while (std::getline(csv, line)) rows += line.rfind(study + ",", 0) == 0;
    EXPECT_GE(rows, 4);
    const io::Image png = io::readPng(dir / (study + ".png"));
    EXPECT_EQ(png.width, 1000);
    EXPECT_TRUE(std::filesystem::file_size(dir / (study + ".svg")) > 1000);
  }
}

// A user's run writes into out/sweep of the working folder; the repository's CSVs and charts are
// rewritten only with --ship (or named folders).
TEST(Sweep, ARunWritesIntoOutSweepHereNotIntoTheRepository) {
  test::TempDir dir;
  const std::filesystem::path source = TIDEPOOL_SOURCE_DIR;
  const std::vector<std::filesystem::path> shipped = {
      source / "bench/results/ripples-dispersion.csv", source / "bench/results/ripples-dispersion.chart.json",
      source / "docs/charts/ripples-dispersion.png", source / "docs/charts/ripples-dispersion.svg"};
  std::vector<std::filesystem::file_time_type> before;
  for (const auto& f : shipped) before.push_back(std::filesystem::last_write_time(f));
  const auto r = test::runProcess(
      {"sh", "-c", "cd '" + dir.path().string() + "' && exec '" TIDEPOOL_EXE "' sweep ripples-dispersion --quick"});
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("rows to out/sweep/ripples-dispersion.csv"), std::string::npos) << r.out;
  for (const char* file :
       {"ripples-dispersion.csv", "ripples-dispersion.chart.json", "ripples-dispersion.png", "ripples-dispersion.svg"})
    EXPECT_TRUE(std::filesystem::exists(dir / "out/sweep" / file)) << file;
  for (std::size_t i = 0; i < shipped.size(); ++i)
    EXPECT_EQ(std::filesystem::last_write_time(shipped[i]), before[i]) << shipped[i];
}

TEST(Sweep, UnknownStudyIsAUsageError) {
  auto r = test::runTidepool({"sweep", "balls-nope"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.errLines().size(), 1u) << r.err;
}

// Rows measured on another machine (the GPU machine has no gnuplot) redraw the same chart here;
// a CSV that does not match its chart settings is refused with one line naming file and line.
TEST(Sweep, ChartsRedrawFromCsvMeasuredElsewhere) {
  test::TempDir measured, drawn, redrawn;
  auto run = test::runTidepool(
      {"sweep", "swarm-orbit", "--quick", "--csv-dir", measured.path().string(), "--chart-dir", drawn.path().string()});
  ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
  ASSERT_TRUE(std::filesystem::exists(measured / "swarm-orbit.chart.json"));
  auto redraw = test::runTidepool({"sweep", "swarm-orbit", "--from-csv", "--csv-dir", measured.path().string(),
                                   "--chart-dir", redrawn.path().string()});
  ASSERT_EQ(redraw.exitCode, 0) << redraw.out << redraw.err;
  auto text = [](const std::filesystem::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(text(drawn / "swarm-orbit.svg"), text(redrawn / "swarm-orbit.svg"));

  {
    std::ofstream csv(measured / "swarm-orbit.csv", std::ios::app);
    csv << "swarm-orbit,swarm,verlet,0.01,1,1M,not-a-number,1,1,1,1,1,0,\"dev\"\n";  // 2 metrics
  }
  auto bad = test::runTidepool({"sweep", "swarm-orbit", "--from-csv", "--csv-dir", measured.path().string(),
                                "--chart-dir", redrawn.path().string()});
  EXPECT_EQ(bad.exitCode, 1);
  ASSERT_EQ(bad.errLines().size(), 1u) << bad.err;
  EXPECT_NE(bad.err.find("swarm-orbit.csv:"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("gpu_ms_per_sim_s 'not-a-number' is not a number"), std::string::npos) << bad.err;

  auto missing = test::runTidepool({"sweep", "swarm-precision", "--from-csv", "--csv-dir", measured.path().string()});
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_EQ(missing.errLines().size(), 1u) << missing.err;
}

TEST(Sweep, CsvRoundTripKeepsMethodNamesWithCommasAndQuotes) {
  test::TempDir dir;
  sweep::Result r;
  r.model = "ripples";
  r.metrics = {"err"};
  r.chart.title = "t";
  sweep::Row row;
  row.method = "phase error, 10 cells \"fine\"";
  row.resolution = "32x32";
  row.metrics = {0.5};
  row.x = 2;
  row.y = 0.5;
  r.rows = {row};
  sweep::writeCsv(r, "study", "GPU, model 1", dir / "s.csv");
  sweep::writeChartSpec(r, dir / "s.chart.json");
  std::string device;
  const sweep::Result back = sweep::readResult(dir / "s.csv", dir / "s.chart.json", device);
  ASSERT_EQ(back.rows.size(), 1u);
  EXPECT_EQ(back.rows[0].method, row.method);
  EXPECT_EQ(back.rows[0].y, 0.5);
  EXPECT_EQ(device, "GPU, model 1");
}
