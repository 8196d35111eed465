// fp16 state storage of particle life (the life-precision study): one GPU step from a state of
// half floats equals a double-precision CPU step within one half-float rounding of the result;
// the fp32 step equals it to float round-off; the CPU reference itself equals the O(N^2) brute
// force; a storage change converts the running state; a fp16 scene renders like a fp32 one.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/packing.hpp>

#include "io/png.h"
#include "reference/life_reference.h"
#include "sim/life/life.h"
#include "sim/life/measure/life_cpu.h"
#include "support/gl_test.h"
#include "support/run_process.h"

using namespace tidepool;
using namespace tidepool::life;

namespace {

using LifeTest = test::GlTest;

// Spacing of half floats around |x| (2^-24 below the normal range).
double halfUlp(double x) {
  const double a = std::abs(x);
  return a < std::ldexp(1.0, -14) ? std::ldexp(1.0, -24) : std::ldexp(1.0, int(std::floor(std::log2(a))) - 10);
}

Rules articleDensity(int n, bool looping, std::uint32_t seed) {
  const float scale = std::sqrt(float(n) / 65536.0f);
  return generateRules({.species = 6,
                        .particleCount = n,
                        .size = {1024.0f * scale, 576.0f * scale},
                        .loopingBorders = looping,
                        .seed = seed});
}

struct StepCheck {
  double worstPos = 0, worstVel = 0;  // max over particles of |GPU - CPU| / allowed
  double meanPosError = 0;            // world units
};

// One Euler step of `model` (ids tracked from its current state) against the CPU in double, from
// exactly the state the GPU holds. Allowed: `ulps` half-float roundings of the result plus
// float round-off of the force (1e-5 of the sum of |contributions|, as the force test asserts).
StepCheck stepAgainstCpu(Life& model, const Rules& rules, float dt, double ulps) {
  model.trackIds(true);
  std::vector<CpuParticle> cpu = cpuState(model.downloadPositions(), model.downloadVelocities());
  const std::vector<CpuForce> forces = cpuForces(rules, cpu);
  cpuStepEuler(rules, cpu, dt);
  model.stepOnce(dt);
  const std::vector<std::uint32_t> ids = model.ids();
  const std::vector<glm::vec4> pos = model.downloadPositions(), vel = model.downloadVelocities();
  StepCheck c;
  for (std::size_t k = 0; k < pos.size(); ++k) {
    const CpuParticle& want = cpu[ids[k]];
    const double forceSlop = 1e-5 * (forces[ids[k]].scale + 1.0) * dt;
    const glm::dvec2 dp = cpuBoxDelta(rules, want.pos, glm::dvec2(pos[k])), dv = glm::dvec2(vel[k]) - want.vel;
    for (int a = 0; a < 2; ++a) {
      c.worstPos = std::max(c.worstPos, std::abs(dp[a]) / (ulps * halfUlp(want.pos[a]) + forceSlop * dt + 1e-5));
      c.worstVel = std::max(c.worstVel, std::abs(dv[a]) / (ulps * halfUlp(want.vel[a]) + forceSlop + 1e-6));
    }
    EXPECT_EQ(int(pos[k].w), want.species) << "particle " << ids[k];
    c.meanPosError += glm::length(dp) / double(pos.size());
  }
  return c;
}

}  // namespace

TEST_F(LifeTest, CpuReferenceEqualsTheBruteForce) {
  for (bool looping : {false, true}) {
    SCOPED_TRACE(looping ? "looping" : "walls");
    const Rules rules = articleDensity(3000, looping, 4);
    Life model(shaders(), rules);
    const std::vector<glm::vec4> pos = model.downloadPositions();
    const std::vector<CpuForce> binned = cpuForces(rules, cpuState(pos, model.downloadVelocities()));
    const std::vector<reference::ForceSum> brute = reference::bruteForce(rules, pos);
    int interacting = 0;
    for (std::size_t i = 0; i < pos.size(); ++i) {
      ASSERT_LT(glm::length(binned[i].accel - brute[i].force), 1e-9 * (brute[i].scale + 1)) << i;
      interacting += brute[i].scale > 0;
    }
    EXPECT_GT(interacting, int(pos.size()) * 9 / 10);
  }
}

TEST_F(LifeTest, Fp32StepEqualsTheCpuStepToFloatRoundOff) {
  const Rules rules = articleDensity(4096, true, 11);
  Life model(shaders(), rules);
  for (int k = 0; k < 5; ++k) model.stepOnce(0.02f);  // clusters start to form
  // Float round-off is ~2^-24 relative, well under a thousandth of a half-float rounding (2^-11).
  const StepCheck c = stepAgainstCpu(model, rules, 0.02f, 1.0 / 1024);
  EXPECT_LT(c.worstPos, 1.0);
  EXPECT_LT(c.worstVel, 1.0);
}

TEST_F(LifeTest, Fp16StepEqualsTheCpuStepWithinOneHalfFloatRounding) {
  for (bool looping : {false, true}) {
    SCOPED_TRACE(looping ? "looping" : "walls");
    const Rules rules = articleDensity(4096, looping, 11);
    Params params;
    params.storage = Storage::Fp16;
    Life model(shaders(), rules, params);
    ASSERT_EQ(model.positions().size(), 8u * model.count()) << "8 bytes of position per particle";
    ASSERT_EQ(model.velocities().size(), 8u * model.count());
    for (int k = 0; k < 5; ++k) model.stepOnce(0.02f);
    // Storing rounds to nearest: half an ulp, plus what the fp32 arithmetic before it moved.
    const StepCheck c = stepAgainstCpu(model, rules, 0.02f, 0.5);
    EXPECT_LT(c.worstPos, 1.0);
    EXPECT_LT(c.worstVel, 1.0);
    // And fp16 really rounds: a quarter of an ulp on average at |x| ~ a quarter of the box.
    EXPECT_GT(c.meanPosError, 0.1 * halfUlp(0.25 * rules.size.x));
  }
}

TEST_F(LifeTest, AStorageChangeConvertsTheRunningState) {
  const Rules rules = articleDensity(2048, false, 2);
  Life model(shaders(), rules);
  for (int k = 0; k < 3; ++k) model.stepOnce(0.02f);
  model.trackIds(true);
  const std::vector<glm::vec4> before = model.downloadPositions();
  model.params().storage = Storage::Fp16;
  model.stepOnce(0.0f);  // converts, then a step of zero time moves nothing
  EXPECT_EQ(model.storage(), Storage::Fp16);
  EXPECT_NE(model.status().find("fp16 state"), std::string::npos) << model.status();
  const std::vector<glm::vec4> after = model.downloadPositions();
  const std::vector<std::uint32_t> ids = model.ids();
  for (std::size_t k = 0; k < after.size(); ++k) {
    const glm::vec4& p = before[ids[k]];
    ASSERT_EQ(glm::vec2(after[k]), glm::unpackHalf2x16(glm::packHalf2x16(glm::vec2(p)))) << k;
    ASSERT_EQ(after[k].w, p.w);
  }
  model.params().storage = Storage::Fp32;
  model.stepOnce(0.02f);
  EXPECT_EQ(model.storage(), Storage::Fp32);
  EXPECT_EQ(model.positions().size(), 16u * model.count());
}

TEST(LifePrecisionCli, Fp16SceneRendersLikeFp32) {
  test::TempDir dir;
  for (const char* storage : {"fp32", "fp16"})
    dir.write(std::string(storage) + ".json",
              std::string(R"({"model": "life", "params": {"particle_count": 2048, "width": 256, "height": 144,
                  "seed": 3, "model": {"storage": ")") +
                  storage + R"("}}, "clip": {"frames": 1, "width": 128, "height": 72}})");
  for (const char* storage : {"fp32", "fp16"}) {
    auto r = test::runTidepool(
        {"render", (dir / (std::string(storage) + ".json")).string(), "--out", (dir / storage).string(), "--quiet"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
  }
  const io::Image a = io::readPng(dir / "fp32/frame_00000.png"), b = io::readPng(dir / "fp16/frame_00000.png");
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  double lit = 0, diff = 0, channels = 0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) {
    if (i % 4 == 3) continue;  // alpha
    lit += a.rgba[i] > 40;
    diff += std::abs(int(a.rgba[i]) - int(b.rgba[i]));
    ++channels;
  }
  EXPECT_GT(lit, 0.05 * channels) << "particles are drawn";
  EXPECT_LT(diff / channels, 1.0) << "positions moved by at most 1/32 of a pixel";
}
