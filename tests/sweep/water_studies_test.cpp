// The water studies (fluid-density, water-front, fluid-stability), quick runs on
// llvmpipe through the program, as the GPU machine runs them: rows of both models in one CSV with
// the columns "method": "auto" reads, a CSV that reads back exactly as written (and redraws), and
// measurements ordered as the physics says.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>

#include "io/png.h"
#include "support/gl_test.h"
#include "support/run_process.h"
#include "support/sweep_column.h"
#include "sweep/sweep.h"

using namespace tidepool;

namespace {

std::string text(const std::filesystem::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Runs a quick study with --no-chart, checks its header, redraws it with --from-csv, reads it
// back, writes what was read again and checks that the two CSVs are the same text.
sweep::Result quickStudy(const test::TempDir& dir, const std::string& study, const std::string& metrics) {
  auto run = test::runTidepool({"sweep", study, "--quick", "--no-chart", "--csv-dir", dir.path().string()});
  EXPECT_EQ(run.exitCode, 0) << run.out << run.err;
  const std::string csv = text(dir / (study + ".csv"));
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "study,model,method,dt,substeps,resolution,gpu_ms_per_sim_s," + metrics +
                                               ",chart_x,chart_y,stable,pareto,device");
  auto redraw = test::runTidepool(
      {"sweep", study, "--from-csv", "--csv-dir", dir.path().string(), "--chart-dir", dir.path().string()});
  EXPECT_EQ(redraw.exitCode, 0) << redraw.out << redraw.err;
  EXPECT_EQ(io::readPng(dir / (study + ".png")).width, 1000);
  std::string device;
  const sweep::Result r = sweep::readResult(dir / (study + ".csv"), dir / (study + ".chart.json"), device);
  sweep::writeCsv(r, study, device, dir / "again.csv");
  EXPECT_EQ(text(dir / "again.csv"), csv) << "the CSV does not read back as it was written";
  return r;
}

const sweep::Row& find(const sweep::Result& r, const std::string& model, const std::string& method, double dt) {
  for (const sweep::Row& row : r.rows)
    if (row.model == model && row.method == method && std::abs(row.dt - dt) < 1e-9) return row;
  ADD_FAILURE() << "no " << model << " row '" << method << "' at dt = " << dt;
  static const sweep::Row none;
  return none;
}

}  // namespace

// A study of several models writes each row's model; a row without one takes the result's, and
// reads back without one.
TEST(WaterStudies, RowModelsRoundTripThroughTheCsv) {
  test::TempDir dir;
  sweep::Result r = sweep::emptyResult("water", {"error"});
  for (const char* model : {"balls", "fluid", ""}) {
    sweep::Row row;
    row.model = model;
    row.method = "m, 1";
    row.metrics = {0.5};
    r.rows.push_back(row);
  }
  sweep::writeCsv(r, "s", "dev", dir / "s.csv");
  sweep::writeChartSpec(r, dir / "s.chart.json");
  const std::string csv = text(dir / "s.csv");
  EXPECT_NE(csv.find("\ns,balls,\"m, 1\","), std::string::npos) << csv;
  EXPECT_NE(csv.find("\ns,fluid,\"m, 1\","), std::string::npos) << csv;
  EXPECT_NE(csv.find("\ns,water,\"m, 1\","), std::string::npos) << csv;
  std::string device;
  const sweep::Result back = sweep::readResult(dir / "s.csv", dir / "s.chart.json", device);
  ASSERT_EQ(back.rows.size(), 3u);
  EXPECT_EQ(back.model, "water");
  EXPECT_EQ(back.rows[0].model, "balls");
  EXPECT_EQ(back.rows[1].model, "fluid");
  EXPECT_EQ(back.rows[2].model, "") << "the result's own model reads back as none of the row's";
  EXPECT_EQ(device, "dev");
}

// The resting tank: the fluid's density error falls with its iterations, the balls' with their
// step (t_c = 20 dt: a stiffer contact overlaps less), both on the fluid's kernel.
TEST(WaterStudies, FluidDensityFallsWithIterationsAndBallsWithDt) {
  test::TempDir dir;
  const sweep::Result r = quickStudy(dir, "fluid-density", "density_error_mean,density_error_max,iterations");
  ASSERT_EQ(r.rows.size(), 4u);
  const std::size_t mean = test::metricColumn(r, "density_error_mean"),
                    max = test::metricColumn(r, "density_error_max"), iterations = test::metricColumn(r, "iterations");
  for (const sweep::Row& row : r.rows) {
    SCOPED_TRACE(row.model + " " + row.method);
    EXPECT_TRUE(row.model == "balls" || row.model == "fluid");
    EXPECT_TRUE(row.stable);
    EXPECT_GT(row.metrics[mean], 0.0);
    EXPECT_LT(row.metrics[mean], 0.05) << "a resting tank compressed by more than 5%";
    EXPECT_GE(row.metrics[max], row.metrics[mean]);
    EXPECT_GT(row.costMsPerSimS, 0.0);
    EXPECT_EQ(row.substeps, 1);
    EXPECT_EQ(row.y, row.metrics[mean]);
  }
  const sweep::Row& one = find(r, "fluid", "pbf, 1 iterations", 2e-3);
  const sweep::Row& four = find(r, "fluid", "pbf, 4 iterations", 2e-3);
  EXPECT_EQ(one.metrics[iterations], 1.0);
  EXPECT_EQ(four.metrics[iterations], 4.0);
  EXPECT_LE(four.metrics[mean], 1.1 * one.metrics[mean]) << "4 iterations compress more than 1";
  const std::string balls = "spring-dashpot tc = 20 dt, symplectic-euler";
  const sweep::Row& fine = find(r, "balls", balls, 2e-4);
  const sweep::Row& coarse = find(r, "balls", balls, 4e-4);
  EXPECT_EQ(fine.metrics[iterations], 0.0);
  EXPECT_LT(fine.metrics[mean], coarse.metrics[mean]) << "t_c = 4 ms overlaps more than t_c = 8 ms";
}

// The dam break at d = 0.04 and 0.02 m: the finest run of each model is its own reference (zero
// error), the coarse one differs by a finite amount, and at each d the two models' fronts differ
// by the same finite amount in both rows.
TEST(WaterStudies, WaterFrontIsMeasuredAgainstTheFinestRunOfEachModel) {
  test::TempDir dir;
  const sweep::Result r = quickStudy(dir, "water-front", "front_error,front_vs_other_model,iterations");
  ASSERT_EQ(r.rows.size(), 4u);
  const std::size_t error = test::metricColumn(r, "front_error"), other = test::metricColumn(r, "front_vs_other_model"),
                    iterations = test::metricColumn(r, "iterations");
  std::map<std::string, std::map<std::string, const sweep::Row*>> rows;  // model -> resolution -> row
  for (const sweep::Row& row : r.rows) {
    SCOPED_TRACE(row.model + " " + row.resolution);
    EXPECT_TRUE(row.stable);
    EXPECT_EQ(row.method, row.model == "fluid" ? "pbf, 4 iterations" : "spring-dashpot tc = 20 dt, symplectic-euler");
    EXPECT_EQ(row.metrics[iterations], row.model == "fluid" ? 4.0 : 0.0);
    EXPECT_TRUE(std::isfinite(row.metrics[other]));
    EXPECT_GT(row.metrics[other], 0.0);
    EXPECT_LT(row.metrics[other], 0.3) << "the two models' fronts differ by more than 0.3 a";
    rows[row.model][row.resolution.substr(0, row.resolution.find(','))] = &row;
  }
  for (const char* model : {"balls", "fluid"}) {
    SCOPED_TRACE(model);
    ASSERT_EQ(rows[model].size(), 2u);
    const sweep::Row& coarse = *rows[model]["d = 0.04 m"];
    const sweep::Row& finest = *rows[model]["d = 0.02 m"];
    EXPECT_EQ(finest.metrics[error], 0.0);
    EXPECT_GT(coarse.metrics[error], 0.0);
    EXPECT_LT(coarse.metrics[error], 0.3) << "d = 0.04 m is no dam break of d = 0.02 m";
    EXPECT_NEAR(coarse.dt, 2 * finest.dt, 1e-9) << "dt proportional to d";
  }
  for (const char* d : {"d = 0.04 m", "d = 0.02 m"})
    EXPECT_EQ(rows["balls"][d]->metrics[other], rows["fluid"][d]->metrics[other]);
}

// The resting tank at 1 and 4 iterations: the bisection finds a limit inside 2–64 ms (so the fluid
// is stable at 2 ms and fails by 64), more iterations allow a larger step, and at each limit the
// derived floor compression is of order 10% (the premise of the compression law).
TEST(WaterStudies, FluidStabilityLimitLiesInTheSearchedRangeAndGrowsWithIterations) {
  test::TempDir dir;
  const sweep::Result r = quickStudy(dir, "fluid-stability", "iterations,floor_compression,max_speed");
  const std::size_t iterations = test::metricColumn(r, "iterations"),
                    compression = test::metricColumn(r, "floor_compression");
  std::map<int, const sweep::Row*> measured, theory;
  for (const sweep::Row& row : r.rows) {
    EXPECT_EQ(row.model, "") << "every row is the result's model";
    if (row.method == "tank: measured") measured[int(row.metrics[iterations])] = &row;
    if (row.method == "tank: theory, floor compression of the tank at k = 4")
      theory[int(row.metrics[iterations])] = &row;
  }
  ASSERT_EQ(measured.size(), 2u);
  ASSERT_EQ(theory.size(), 2u);
  for (const auto& [k, row] : measured) {
    SCOPED_TRACE(k);
    EXPECT_GT(row->dt, 2e-3);
    EXPECT_LT(row->dt, 64e-3);
    EXPECT_EQ(row->y, 1e3 * row->dt);
    EXPECT_GT(row->metrics[compression], 0.03);
    EXPECT_LT(row->metrics[compression], 0.5);
  }
  EXPECT_GT(measured[4]->dt, 1.5 * measured[1]->dt) << "4 iterations hold a larger step than 1";
  EXPECT_NEAR(theory[4]->dt / theory[1]->dt, 2.0, 1e-5) << "the compression law grows as sqrt(k)";
  EXPECT_NEAR(theory[4]->dt, measured[4]->dt, 1e-5 * measured[4]->dt) << "drawn through the measured k = 4";
}
