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

// The scene's own probes (params.probes, sim/water/probes.h) are columns of the CSV: a gauge's
// height and an obstacle's pose and velocity, for each model.
TEST(Validate, SceneProbesAreColumnsForBothModels) {
  test::TempDir dir;
  for (const char* model : {"balls", "fluid"}) {
    const bool balls = std::string(model) == "balls";
    dir.write("tank.json", std::string(R"({"model": ")") + model + R"(", "params": {
        "particles": {)" + (balls ? R"("radius": 0.01)" : R"("spacing": 0.02)") +
                               R"(, "domain_max": [0.4, 0.2, 0.3], "fill": "slab", "slab_height": 0.1},
        "obstacles": [{"shape": "sphere", "centre": [0.3, 0.1, 0.2], "size": [0.03, 0.03, 0.03],
                       "path": {"kind": "oscillate", "amplitude": [0, 0, 0.05], "period": 1}}],
        "probes": [{"kind": "gauge", "at": [0.15, 0.1, 0]}, {"kind": "body", "obstacle": 0},
                   {"kind": "force", "wall": "-z"}]}})");
    auto r = test::runTidepool({"validate", (dir / "tank.json").string(), "--probe", "probes", "--every", "10",
                                "--until", "0.02", "--csv", (dir / "p.csv").string()});
    ASSERT_EQ(r.exitCode, 0) << model << ": " << r.err;
    std::string header;
    const auto rows = readCsv(dir / "p.csv", header);
    EXPECT_EQ(header,
              "time_s,count,nan,gauge0_height_m,body1_x_m,body1_y_m,body1_z_m,body1_qw,body1_qx,body1_qy,"
              "body1_qz,body1_vx_m_s,body1_vy_m_s,body1_vz_m_s,body1_wx_rad_s,body1_wy_rad_s,body1_wz_rad_s,"
              "force2_normal_n")
        << model;
    ASSERT_GE(rows.size(), 2u) << model;
    for (const auto& row : rows) {
      ASSERT_EQ(row.size(), 18u) << model;
      // The slab's height; the balls': its 5 whole HCP layers, 2r·√(2/3) apart.
      const double height = balls ? 5 * 0.02 * std::sqrt(2.0 / 3.0) : 0.1;
      EXPECT_NEAR(row[3], height, 0.01 * height) << model;
      // The path z = 0.2 + 0.05 sin(2πt): the pose the obstacle was placed at for the step just taken.
      EXPECT_NEAR(row[6], 0.2 + 0.05 * std::sin(2 * M_PI * row[0]), 0.05 * 2 * M_PI * 0.002) << model;
      EXPECT_NEAR(row[7], 1.0, 1e-6) << model << ": unturned";
    }
    EXPECT_GT(rows.back()[13], 0.1) << model << ": moving up";
    EXPECT_GT(rows.back()[17], 0.0) << model << ": the water pushes the floor down";
  }
}

TEST(Validate, ProbesTheSceneCannotMeasureAreOneLineErrors) {
  test::expectOneLineError({"validate", "dam-break", "--probe", "probes"},
                           "--probe probes: the scene 'Dam break' lists no probes (params.probes)");
  test::TempDir dir;
  const std::string head =
      R"({"model": "fluid", "params": {"particles": {"spacing": 0.02, "domain_max": [0.4, 0.2, 0.3],
      "fill": "slab", "slab_height": 0.1}, "probes": )";
  const std::pair<const char*, const char*> cases[] = {
      {R"([{"kind": "body", "obstacle": 2}]}})", "probes[0]: obstacle 2 does not exist: the scene has 0 obstacles"},
      {R"([{"kind": "gauge", "at": [0.5, 0.1, 0]}]}})",
       "probes[0]: the gauge at (0.5, 0.1) is not inside the domain's x (0, 0.4) and y (0, 0.2)"},
      {R"([{"kind": "torque"}]}})", "probes[0].kind = 'torque' is not one of: gauge, pressure, force, body"},
      {R"([{"kind": "force", "wall": "top"}]}})", "probes[0].wall = 'top' is not one of: none, -x, +x, -y, +y, -z, +z"},
      {R"([{"kind": "force", "obstacle": 1}]}})", "probes[0]: obstacle 1 does not exist: the scene has 0 obstacles"},
      {R"([{"kind": "pressure", "at": [0.2, 0.1, 0.5]}]}})",
       "probes[0]: the pressure probe at (0.2, 0.1, 0.5) is not inside the domain"},
      {R"([{"kind": "gauge", "radius": -1}]}})", "probes[0].radius"},
      {R"({"kind": "gauge"}}})", "probes"}};
  for (const auto& [probes, message] : cases) {
    dir.write("bad.json", head + probes);
    test::expectOneLineError({"validate", (dir / "bad.json").string(), "--probe", "probes"}, message);
  }
}

TEST(Validate, APressureProbeOnBallsIsOneLineBeforeAnyOutput) {
  test::TempDir dir;
  dir.write("balls.json", R"({"model": "balls", "params": {"particles": {"radius": 0.01,
      "domain_max": [0.4, 0.2, 0.3], "fill": "slab", "slab_height": 0.1},
      "probes": [{"kind": "pressure", "at": [0.2, 0.1, 0.05]}]}})");
  test::expectOneLineError(
      {"validate", (dir / "balls.json").string(), "--probe", "probes", "--csv", (dir / "p.csv").string()},
      "balls: a pressure probe reads the fluid solver's pressure");
  EXPECT_FALSE(std::filesystem::exists(dir / "p.csv"));
}
