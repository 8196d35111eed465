// A scene too big for the device fails before anything is allocated, with one line that says how
// many particles it would make, how many fit, the limit that binds and the key to change.
#include <gtest/gtest.h>

#include "support/gl_test.h"
#include "support/one_line_error.h"

using namespace tidepool;
using test::expectOneLineError;

namespace {
std::vector<std::string> render(const test::TempDir& dir, const std::string& name, const std::string& json) {
  dir.write(name, json);
  return {"render", (dir / name).string(), "--frames", "1", "--out", (dir / "o").string()};
}
}  // namespace

TEST(GpuLimits, BallsRadiusTooSmallForTheDevice) {
  test::TempDir dir;
  const auto r = expectOneLineError(
      render(dir, "tiny.json", R"({"model": "balls", "params": {"particles": {"radius": 0.0001, "fill": "block",
                                   "fill_min": [0, 0, 0], "fill_max": [1, 1, 1], "domain_max": [1, 1, 1]}}})"),
      "balls: particles.radius = 0.0001 m would make about 1.77e+11 balls, but at most ", 1);
  EXPECT_NE(r.err.find("raise particles.radius"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
}

TEST(GpuLimits, FluidSpacingTooSmallForTheDevice) {
  test::TempDir dir;
  expectOneLineError(render(dir, "fine.json", R"({"model": "fluid", "params": {"particles": {"spacing": 0.0002,
                                              "fill": "block", "fill_min": [0, 0, 0], "fill_max": [1, 1, 1],
                                              "domain_max": [1, 1, 1]}}})"),
                     "fluid: particles.spacing = 0.0002 m would make about 1.25e+11 particles, but at most ", 1);
}

TEST(GpuLimits, ObstaclesCountTowardsTheLimit) {
  test::TempDir dir;
  expectOneLineError(
      render(dir, "big.json", R"({"model": "balls", "params": {"particles": {"radius": 0.0005, "fill": "none"},
             "obstacles": [{"shape": "sphere", "centre": [0.5, 0.5, 0.5], "size": [0.4, 0.4, 0.4]}]}})"),
      "balls: particles.radius = 0.0005 m would make about ", 1);
}

TEST(GpuLimits, TapCountsTowardsTheLimit) {
  test::TempDir dir;
  expectOneLineError(render(dir, "tap.json", R"({"model": "balls", "params": {"particles": {"fill": "none",
                                             "max_particles": 1000}, "tap": {"enabled": true, "max": 5000}}})"),
                     "would make about 5000 balls, but at most 1000 fit (max_particles = 1000)", 1);
}
