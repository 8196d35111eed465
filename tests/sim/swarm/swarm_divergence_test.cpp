// Failing loudly: a swarm step far too long for the field (a particle kicked to
// absurd speed, or fp16 state overflowing to infinity) is caught by the non-blocking watch,
// reported with the integrator, storage and dt, and undone exactly from the last good state with
// half the time step; a headless run exits non-zero with the message.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/swarm/swarm.h"
#include "support/gl_test.h"
#include "support/one_line_error.h"
#include "support/run_process.h"

using namespace tidepool;
using namespace tidepool::sim;

namespace {

using SwarmTest = test::GlTest;

// A ring of 256 particles on the circular orbit r = 0.5 around one attractor s = 1 (ε = 0): the
// period is π s, and 200 steps per orbit keep it on its orbit.
SwarmParams ringParams(Storage storage) {
  SwarmParams p;
  p.preset = Preset::None;
  p.gravity = 0.0f;
  p.friction = 0.0f;
  p.epsilon = 0.0f;
  p.bounce = false;
  p.storage = storage;
  p.particles = 256;
  return p;
}

void placeRing(Swarm& swarm) {
  swarm.setAspect(1.0);
  swarm.setExtraAttractors({{{0.0, 0.0}, 1.0}});
  std::vector<SwarmParticle> start;
  for (int k = 0; k < 256; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 256;
    start.push_back({glm::vec2(0.5 * std::cos(a), 0.5 * std::sin(a)), glm::vec2(-std::sin(a), std::cos(a))});
  }
  swarm.upload(start);
}

// Frames of one step each until `frames` or a divergence; returns the frames run.
int runFrames(Swarm& swarm, int frames, double dt) {
  int i = 0;
  for (; i < frames && !swarm.divergence(); ++i) {
    swarm.stepOnce(dt);
    swarm.watch();
    if (i % 8 == 7) swarm.flushChecks();  // keeps the test short; the app never blocks
  }
  swarm.flushChecks();
  return i;
}

}  // namespace

TEST_F(SwarmTest, SeedSettingsAreNeverFlagged) {
  SwarmParams p;
  p.particles = 1 << 14;
  Swarm swarm(shaders(), p);
  runFrames(swarm, 300, 1.0 / 120);
  EXPECT_FALSE(swarm.divergence().has_value()) << swarm.divergence()->message;
  EXPECT_LT(swarm.speedBound(), 1e3) << "the bound is on the scale of the field, not arbitrary";
}

TEST_F(SwarmTest, BlowUpIsReportedAndRecoveredWithHalfTheStep) {
  const double dt = std::numbers::pi / 200;
  Swarm swarm(shaders(), ringParams(Storage::Fp32)), twin(shaders(), ringParams(Storage::Fp32));
  placeRing(swarm);
  placeRing(twin);
  runFrames(swarm, 40, dt);
  ASSERT_FALSE(swarm.divergence().has_value()) << swarm.divergence()->message;

  const int wild = runFrames(swarm, 40, 1000.0);  // symplectic Euler kicks every particle to |v| = 2000
  ASSERT_TRUE(swarm.divergence().has_value());
  const std::string message = swarm.divergence()->message;
  EXPECT_EQ(message.rfind("swarm diverged by t = ", 0), 0u) << message;
  EXPECT_NE(message.find("a particle moves at 2.0"), std::string::npos) << message;  // 2000 units/s
  EXPECT_NE(message.find("(symplectic_euler, fp32, dt = 1e+03 s)"), std::string::npos) << message;
  EXPECT_NE(message.find("halve the time step and resume from the last good state"), std::string::npos) << message;
  const double failedAt = swarm.divergence()->time;

  const std::optional<std::uint64_t> back = swarm.recover();
  ASSERT_TRUE(back);
  EXPECT_EQ(*back, std::uint64_t(wild)) << "the good state is the last before the long steps";
  EXPECT_FALSE(swarm.divergence().has_value());
  EXPECT_EQ(swarm.params().substeps, 2) << "half the time step, same simulated time per frame";
  const double goodTime = swarm.time();
  EXPECT_LT(goodTime, failedAt);
  EXPECT_NEAR(goodTime, 40 * dt, 1e-9) << "the newest state judged good: the last one before the long steps";
  while (twin.time() < goodTime - 1e-9) twin.stepOnce(dt);
  const std::vector<SwarmParticle> restored = swarm.download(), replay = twin.download();
  ASSERT_EQ(restored.size(), replay.size());
  for (std::size_t i = 0; i < restored.size(); ++i) {
    ASSERT_EQ(restored[i].pos, replay[i].pos) << i;
    ASSERT_EQ(restored[i].vel, replay[i].vel) << i;
  }
}

TEST_F(SwarmTest, Fp16OverflowIsReportedAsNonFinite) {
  Swarm swarm(shaders(), ringParams(Storage::Fp16));
  placeRing(swarm);
  runFrames(swarm, 16, std::numbers::pi / 200);
  ASSERT_FALSE(swarm.divergence().has_value()) << swarm.divergence()->message;
  runFrames(swarm, 16, 1e5);  // |v| = 2·10⁵ > 65504, the largest half float
  ASSERT_TRUE(swarm.divergence().has_value());
  const std::string message = swarm.divergence()->message;
  EXPECT_NE(message.find("256 particles are NaN or infinite"), std::string::npos) << message;
  EXPECT_NE(message.find("fp16"), std::string::npos) << message;
}

TEST_F(SwarmTest, WithoutAGoodStateRecoveryIsRefused) {
  Swarm swarm(shaders(), ringParams(Storage::Fp32));
  placeRing(swarm);
  EXPECT_FALSE(swarm.recover());
}

TEST(SwarmDivergenceCli, HeadlessRunExitsNonZeroWithTheMessage) {
  test::TempDir dir;
  // One simulated second per step (4 x 0.25 s) from rest around an unsoftened attractor:
  // particles that come close to it are kicked to a thousand units/s (12x the bound).
  dir.write("boom.json",
            R"({"model": "swarm", "params": {"particles": 4096, "epsilon": 0, "speed": 4, "frame_seconds": 0.25,
      "preset": "central_attractive"}, "clip": {"frames": 24, "fps": 4, "width": 32, "height": 32}})");
  const std::string last = test::expectRenderFails((dir / "boom.json").string(), (dir / "f").string(),
                                                   "tidepool: error: swarm diverged by t = ");
  EXPECT_NE(last.find("symplectic_euler, fp32, dt = 1 s"), std::string::npos) << last;
}
