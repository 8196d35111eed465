// Failing loudly: particle life past symplectic Euler's limit on the central force
// (ω·dt > 2) is caught by the non-blocking watch, reported with the integrator, storage and dt,
// and undone exactly: the restored state is the one a twin run reaches at the same time, and
// with half the time step the run goes on without being flagged.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "sim/life/life.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::life;

namespace {

using LifeTest = test::GlTest;

// Particles feel only the central force c = 1000 /s² (ω = 31.6 /s; no friction), so each is a
// harmonic oscillator: symplectic Euler is stable for dt < 2/ω = 0.063 s. The force table's
// radius (1536) only sets the grid cell, and with it the watch's speed bound. The particles
// start within 600 of the centre so that a stable run never reaches the walls (whose clamp and
// reflection would pump energy into an oscillator stretched by a coarse step).
Rules oscillators() {
  Rules rules = generateRules({.species = 2,
                               .particleCount = 1024,
                               .size = {4096.0f, 4096.0f},
                               .friction = 0,
                               .centralForce = 1000,
                               .seed = 3});
  for (Species& s : rules.species)
    for (Force& f : s.forces) f = {0, 0, 1536, 0};
  return rules;
}

void startInside(Life& model) {
  std::vector<glm::vec4> pos = model.downloadPositions();
  for (glm::vec4& p : pos) p = glm::vec4(glm::vec2(p) * (600.0f / 2048.0f), p.z, p.w);
  model.upload(pos, model.downloadVelocities());
}

// The state as a sorted set: the grid reorders particles every step, and with no pair forces
// each particle's step depends on itself alone, so two runs agree exactly as sets.
std::vector<std::array<float, 5>> stateSet(const Life& model) {
  const std::vector<glm::vec4> pos = model.downloadPositions(), vel = model.downloadVelocities();
  std::vector<std::array<float, 5>> out;
  for (std::size_t i = 0; i < pos.size(); ++i) out.push_back({pos[i].x, pos[i].y, pos[i].w, vel[i].x, vel[i].y});
  std::sort(out.begin(), out.end());
  return out;
}

void runFrames(Life& model, int frames, gl::GpuProfiler& profiler) {
  for (int i = 0; i < frames && !model.divergence(); ++i) {
    model.step(profiler);                 // dt = maxDt
    if (i % 8 == 7) model.flushChecks();  // keeps the test short; the app never blocks
  }
  model.flushChecks();
}

}  // namespace

TEST_F(LifeTest, ArticleDefaultsAreNeverFlagged) {
  Life model(shaders(), generateRules({.species = 6, .particleCount = 2048, .size = {256.0f, 144.0f}, .seed = 5}));
  gl::GpuProfiler profiler;
  runFrames(model, 120, profiler);
  EXPECT_FALSE(model.divergence().has_value()) << model.divergence()->message;
}

TEST_F(LifeTest, BlowUpIsReportedAndRecoveredWithHalfTheStep) {
  gl::GpuProfiler profiler;
  Life model(shaders(), oscillators()), twin(shaders(), oscillators());
  startInside(model);
  startInside(twin);
  model.params().maxDt = twin.params().maxDt = 0.025f;  // ω·dt = 0.79: stable, good states are kept
  runFrames(model, 40, profiler);
  ASSERT_FALSE(model.divergence().has_value()) << model.divergence()->message;

  model.params().maxDt = 0.1f;  // ω·dt = 3.2 > 2
  runFrames(model, 400, profiler);
  ASSERT_TRUE(model.divergence().has_value()) << "omega dt = 3.2 must blow up";
  const std::string message = model.divergence()->message;
  EXPECT_EQ(message.rfind("life diverged by t = ", 0), 0u) << message;
  EXPECT_NE(message.find("(euler, fp32, dt = 0.1 s)"), std::string::npos) << message;
  EXPECT_NE(message.find("halve the time step and resume from the last good state"), std::string::npos) << message;
  const double failedAt = model.divergence()->time;

  ASSERT_TRUE(model.recover());
  EXPECT_FALSE(model.divergence().has_value());
  EXPECT_FLOAT_EQ(model.params().maxDt, 0.05f);
  const double goodTime = model.time();
  EXPECT_LT(goodTime, failedAt) << "resumes from a state judged good, before the bad one";
  EXPECT_GE(goodTime, 40 * 0.025 - 1e-6) << "the last good state is the newest one judged good";
  while (twin.time() < goodTime - 1e-9) twin.step(profiler);
  ASSERT_NEAR(twin.time(), goodTime, 1e-9);
  EXPECT_EQ(stateSet(model), stateSet(twin)) << "the restored state is the good one, bit for bit";

  runFrames(model, 64, profiler);  // ω·dt = 1.58 < 2
  EXPECT_FALSE(model.divergence().has_value()) << model.divergence()->message;
  EXPECT_GT(model.time(), goodTime + 60 * 0.05 - 1e-6);
}

TEST_F(LifeTest, WithoutAGoodStateRecoveryIsRefused) {
  Life model(shaders(), oscillators());
  EXPECT_FALSE(model.recover()) << "nothing diverged";
}
