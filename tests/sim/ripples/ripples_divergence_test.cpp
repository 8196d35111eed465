// Failing loudly: a forced blow-up is caught by the non-blocking watch, reported with the method
// and time step, and undone exactly: the last good state is intact and the run continues stably
// with half the time step.
#include <gtest/gtest.h>

#include <random>

#include "sim/ripples/measure/ripples_measure.h"
#include "sim/ripples/ripples.h"
#include "support/gl_test.h"
#include "support/one_line_error.h"

using namespace tidepool;
using namespace tidepool::ripples;

namespace {

using RipplesTest = test::GlTest;

Params unstableAt(double courantNumber) {
  Params p = periodicWaveGrid(32, 32);
  p.frameSeconds = 1.0 / 60;
  p.waveSpeed = float(courantNumber * p.cellSize / p.frameSeconds);  // one step per frame at this C
  return p;
}

void seedNoise(Ripples& r) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1e-3f, 1e-3f);
  std::vector<float> hv(32 * 32 * 2, 0.0f);
  for (std::size_t i = 0; i < hv.size(); i += 2) hv[i] = u(rng);
  r.upload(hv);
}

}  // namespace

TEST_F(RipplesTest, StableRunsAreNeverFlagged) {
  Ripples r(shaders(), unstableAt(0.6));
  seedNoise(r);
  gl::GpuProfiler profiler;
  for (int i = 0; i < 200; ++i) r.step(profiler);
  r.flushChecks();
  EXPECT_FALSE(r.divergence().has_value());
}

TEST_F(RipplesTest, BlowUpIsReportedAndTheLastGoodStateRestored) {
  const Params p = unstableAt(0.75);
  Ripples r(shaders(), p), twin(shaders(), p);  // the twin replays the run to check the restored state
  seedNoise(r);
  seedNoise(twin);
  gl::GpuProfiler profiler;
  int frames = 0;
  for (; frames < 2000 && !r.divergence(); ++frames) {
    r.step(profiler);
    if (frames % 50 == 0) r.flushChecks();  // keeps the test short; the app never blocks
  }
  r.flushChecks();
  ASSERT_TRUE(r.divergence().has_value()) << "C = 0.75 > 1/sqrt(2) must blow up";
  const std::string message = r.divergence()->message;
  const double failedAt = r.divergence()->time;
  EXPECT_NE(message.find("ripples diverged by t = "), std::string::npos) << message;
  EXPECT_NE(message.find("wave rule, dt = "), std::string::npos) << message;
  EXPECT_NE(message.find("C = 0.750 above the limit 1/sqrt(2)"), std::string::npos) << message;
  EXPECT_NE(message.find("halve the time step"), std::string::npos) << message;

  ASSERT_TRUE(r.recover());
  EXPECT_FALSE(r.divergence().has_value());
  EXPECT_EQ(r.params().substeps, 2) << "half the time step";
  const double goodTime = r.time();
  EXPECT_LT(goodTime, failedAt) << "the good state is older than the failed check";
  // The restored state is exactly the twin's at the same time, and it is sane.
  while (twin.time() < goodTime - 1e-9) twin.step(profiler);
  ASSERT_NEAR(twin.time(), goodTime, 1e-9);
  const std::vector<float> restored = r.download(), replay = twin.download();
  ASSERT_EQ(restored, replay);
  for (std::size_t i = 0; i < restored.size(); i += 2) ASSERT_LT(std::abs(restored[i]), r.heightBound());

  // With half the time step (C = 0.375) the run goes on without blowing up.
  for (int i = 0; i < 300; ++i) r.step(profiler);
  r.flushChecks();
  EXPECT_FALSE(r.divergence().has_value());
}

TEST(RipplesDivergenceCli, HeadlessRunExitsNonZeroWithTheMessage) {
  test::TempDir dir;
  dir.write("boom.json", R"({"model": "ripples", "params": {"width": 64, "height": 64, "wave_speed": 10,
      "auto_substeps": false, "substeps": 1, "vel_damping": 0,
      "drops": [{"time": 0, "x": 0.5, "y": 0.5, "radius": 0.05, "depth": -0.05}]},
      "clip": {"frames": 400, "fps": 30, "width": 32, "height": 32}})");
  test::expectRenderFails((dir / "boom.json").string(), (dir / "f").string(),
                          "tidepool: error: ripples diverged by t = ");
}
