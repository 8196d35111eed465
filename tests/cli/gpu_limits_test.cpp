// A scene too big for the device fails before anything is allocated, with one line that says how
// many particles it would make, how many fit, the limit that binds and the key to change.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

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

// Arrays past the storage-block limit run in windows (gl/window.h). With the limit lowered
// to 256 KiB, 20,000 balls step, check their health, save a checkpoint and draw in water mode in
// windows of 16,384; the checkpoint must be the one-block run's byte for byte and the frame its
// picture pixel for pixel (the fragment raster in both: windowed balls are drawn as fragments).
TEST(GpuLimits, BallsPastOneStorageBlockRunInWindowsAsInOne) {
  test::TempDir dir;
  dir.write("box.json", R"({"model": "balls", "params": {
      "particles": {"radius": 0.005, "domain_min": [0, 0, 0], "domain_max": [0.4, 0.25, 0.5], "fill": "block",
                    "fill_min": [0, 0, 0], "fill_max": [0.2, 0.25, 0.4]},
      "engine": {"substeps": 10},
      "view": {"mode": "water",
               "camera": {"target": [0.2, 0.12, 0.15], "distance": 1.0, "yaw": -1.15, "pitch": 0.35}}}})");
  auto bytes = [](const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  std::string checkpoint[2], frame[2];
  for (int windowed = 0; windowed < 2; ++windowed) {
    const std::string out = (dir / ("out" + std::to_string(windowed))).string();
    const auto r = test::runTidepool(
        {"render", (dir / "box.json").string(), "--frames", "3", "--size", "96x64", "--out", out, "--checkpoint",
         out + ".ckpt", "--quiet"},
        windowed ? std::vector<std::string>{"TIDEPOOL_STORAGE_BLOCK_BYTES=262144", "TIDEPOOL_BALLS_RASTER=fragment"}
                 : std::vector<std::string>{"TIDEPOOL_BALLS_RASTER=fragment"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    checkpoint[windowed] = bytes(out + ".ckpt");
    frame[windowed] = bytes(std::filesystem::path(out) / "frame_00002.png");
  }
  ASSERT_GT(checkpoint[0].size(), 20000u * 32u) << "positions and velocities of every ball";
  EXPECT_TRUE(checkpoint[0] == checkpoint[1]) << "the windowed run's state differs";
  ASSERT_FALSE(frame[0].empty());
  EXPECT_TRUE(frame[0] == frame[1]) << "the windowed run's picture differs";
}

TEST(GpuLimits, StorageBlockOverrideIsChecked) {
  test::TempDir dir;
  const std::vector<std::string> args = render(
      dir, "small.json", R"({"model": "balls", "params": {"particles": {"fill": "lattice", "lattice_count": 100}}})");
  expectOneLineError(args, "TIDEPOOL_STORAGE_BLOCK_BYTES = 'abc' is not a byte count", 1,
                     {"TIDEPOOL_STORAGE_BLOCK_BYTES=abc"});
  expectOneLineError(args, "TIDEPOOL_STORAGE_BLOCK_BYTES = '-5' is not a byte count", 1,
                     {"TIDEPOOL_STORAGE_BLOCK_BYTES=-5"});
  expectOneLineError(args,
                     "TIDEPOOL_STORAGE_BLOCK_BYTES = 1000 bytes is below the smallest storage-block limit tidepool "
                     "runs with, 65536 bytes",
                     1, {"TIDEPOOL_STORAGE_BLOCK_BYTES=1000"});
}

// Obstacles are read through buffer textures (GL 4.3 guarantees 65,536 texels): a scene whose
// obstacle particles pass the device's limit is refused with the count and the limit. With the
// limit lowered to GL 4.3's minimum, a sphere of about 150,000 particles is refused; the same
// scene runs at the device's own limit.
TEST(GpuLimits, ObstaclesPastTheBufferTextureLimitAreRefused) {
  test::TempDir dir;
  const std::vector<std::string> args =
      render(dir, "sphere.json", R"({"model": "balls", "params": {"particles": {"radius": 0.002, "fill": "none",
             "domain_max": [0.3, 0.3, 0.3]},
             "obstacles": [{"shape": "sphere", "centre": [0.15, 0.15, 0.15], "size": [0.2, 0.2, 0.2]}]}})");
  expectOneLineError(args,
                     " fixed particles, over this GPU's buffer-texture limit of 65536: make the obstacles smaller or "
                     "the radius larger",
                     1, {"TIDEPOOL_TEXTURE_BUFFER_TEXELS=65536"});
  EXPECT_EQ(test::runTidepool(args).exitCode, 0);
  expectOneLineError(args, "TIDEPOOL_TEXTURE_BUFFER_TEXELS = '1000' is not a texel count of at least 65536", 1,
                     {"TIDEPOOL_TEXTURE_BUFFER_TEXELS=1000"});
}
