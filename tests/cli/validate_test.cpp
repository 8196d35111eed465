// `tidepool validate` writes probe time series: the dam-break surge advances, the column drops,
// no ball is lost; bad probes and non-balls scenes are clear errors.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "support/gl_test.h"
#include "support/one_line_error.h"

using namespace tidepool;

namespace {
std::vector<std::vector<double>> readCsv(const std::filesystem::path& path, std::string& header) {
  std::ifstream in(path);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}
}  // namespace

TEST(Validate, DamBreakProbesShowTheSurgeAndKeepEveryBall) {
  test::TempDir dir;
  dir.write("dam.json", R"({"model": "balls", "params": {
      "particles": {"radius": 0.02, "domain_max": [1, 0.2, 0.6], "fill": "block",
                    "fill_min": [0, 0, 0], "fill_max": [0.25, 0.2, 0.5]},
      "engine": {"dt": 0.0004, "contact_time": 0.008, "restitution": 0.5}}})");
  auto r = test::runTidepool({"validate", (dir / "dam.json").string(), "--every", "100", "--until", "0.24", "--csv",
                              (dir / "p.csv").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::string header;
  const auto rows = readCsv(dir / "p.csv", header);
  EXPECT_EQ(header,
            "time_s,count,nan,kinetic,potential,total,max_overlap_r,mean_overlap_r,front_over_a,height_over_h0");
  ASSERT_EQ(rows.size(), 7u);  // t = 0, 0.04, ..., 0.24
  EXPECT_NEAR(rows.front()[8], 1.0, 0.1) << "the front starts at the column's face (lattice: within a ball)";
  EXPECT_GT(rows.back()[8], rows.front()[8] + 0.3) << "the surge advances";
  EXPECT_LT(rows.back()[9], rows.front()[9] - 0.1) << "the column drops";
  for (const auto& row : rows) {
    EXPECT_EQ(row[1], rows.front()[1]) << "ball count";
    EXPECT_EQ(row[2], 0.0) << "NaN count";
  }
  EXPECT_LT(rows.back()[3] + rows.back()[4], rows.front()[3] + rows.front()[4]) << "dissipation: energy falls";
}

TEST(Validate, BadProbesAndModelsAreOneLineErrors) {
  test::expectOneLineError({"validate", "dam-break", "--probe", "energy,speed"}, "--probe 'speed' is not one of");
  auto ripples = test::runTidepool({"validate", "ripples"});
  EXPECT_EQ(ripples.exitCode, 1);
  EXPECT_NE(ripples.err.find("validate runs balls and fluid scenes"), std::string::npos) << ripples.err;
}
