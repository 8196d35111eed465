// Failing loudly: a balls run past its stability limit is caught by the non-blocking
// watch, reported with the time, contact law, integrator and time step, and recovered from the
// last good state with half the time step, exactly: the restored state is the one a twin run
// reaches at the same time, bit for bit, and both go on alike; a stable run is never flagged.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "sim/balls/balls.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::balls;
using namespace tidepool::water;

namespace {

using BallsTest = test::GlTest;

// A block of balls resting on the floor, springs of contact time 2 ms. Undamped-contact stability
// needs dt < 2/omega0 ~ 0.64 t_c (docs/ACCURACY.md); `dt` picks either side.
Params restingBlock(float dt) {
  Params p;
  p.radius = 0.01f;
  p.domainMin = glm::vec3(0.0f);
  p.domainMax = glm::vec3(0.2f, 0.2f, 0.3f);
  p.fill = Fill::Block;
  p.fillMin = p.domainMin;
  p.fillMax = glm::vec3(0.2f, 0.2f, 0.08f);
  p.contact = Contact::SpringDashpot;
  p.integrator = Integrator::SymplecticEuler;
  p.contactTime = 0.002f;
  p.restitution = 0.5f;
  p.dt = dt;
  p.substeps = 4;
  return p;
}

bool allFiniteInside(const Balls& b) {
  const Params& p = b.params();
  for (const glm::vec4& x : b.positions().read<glm::vec4>(b.count())) {
    if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z)) return false;
    if (glm::any(glm::lessThan(glm::vec3(x), p.domainMin - 1e-4f)) ||
        glm::any(glm::greaterThan(glm::vec3(x), p.domainMax + 1e-4f)))
      return false;
  }
  return true;
}

// Balls that touch only the floor: a square lattice of spacing 3r, each ball resting on the floor,
// away from the side walls. Every force on a ball (its floor contact, gravity) is vertical, so no
// two balls ever come within 2r: each ball's step depends on itself alone. (Balls sharing a grid
// cell are ordered by atomicAdd, which varies between runs, so with ball-ball contacts two runs
// sum the same forces in different orders and part in the last bits.)
void placeOnTheFloor(Balls& b) {
  const Params& p = b.params();
  const float r = b.radius();
  std::vector<glm::vec4> pos, vel;
  for (float y = p.domainMin.y + 2.0f * r; y < p.domainMax.y - 2.0f * r; y += 3.0f * r)
    for (float x = p.domainMin.x + 2.0f * r; x < p.domainMax.x - 2.0f * r; x += 3.0f * r) {
      pos.emplace_back(x, y, p.domainMin.z + r, 1.0f);
      vel.emplace_back(0.0f);
    }
  b.upload(pos, vel);
}

// The state as a sorted set of bit patterns: equal sets mean equal balls, bit for bit, in
// whatever order the grid left them (NaNs included).
std::vector<std::array<std::uint32_t, 8>> stateSet(const Balls& b) {
  const std::vector<glm::vec4> pos = b.downloadPositions(), vel = b.downloadVelocities();
  std::vector<std::array<std::uint32_t, 8>> out(pos.size());
  for (std::size_t i = 0; i < pos.size(); ++i) {
    std::memcpy(out[i].data(), &pos[i], sizeof(glm::vec4));
    std::memcpy(out[i].data() + 4, &vel[i], sizeof(glm::vec4));
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Steps until the watch reports a divergence or `frames` have run, then settles the last check.
void runFrames(Balls& b, int frames, gl::GpuProfiler& profiler) {
  for (int i = 0; i < frames && !b.divergence(); ++i) {
    b.step(profiler);
    if (i % 16 == 15) b.flushChecks();  // keeps the test short; the app never blocks
  }
  b.flushChecks();
}

}  // namespace

TEST_F(BallsTest, StableRunsAreNeverFlagged) {
  Balls b(shaders(), restingBlock(1e-4f));
  gl::GpuProfiler profiler;
  for (int i = 0; i < 120; ++i) b.step(profiler);
  b.flushChecks();
  EXPECT_FALSE(b.divergence().has_value()) << b.divergence()->message;
}

TEST_F(BallsTest, BlowUpIsReportedAndRecoveredWithHalfTheStep) {
  Balls b(shaders(), restingBlock(1e-4f));
  ASSERT_GT(b.count(), 100u);
  gl::GpuProfiler profiler;
  for (int i = 0; i < 40; ++i) b.step(profiler);  // good states are judged and kept
  b.flushChecks();
  ASSERT_FALSE(b.divergence().has_value());
  const float dt = 4e-3f;  // then the user drags dt to twice t_c: far past the limit
  b.params().dt = dt;
  int frames = 0;
  for (; frames < 400 && !b.divergence(); ++frames) {
    b.step(profiler);
    if (frames % 16 == 0) b.flushChecks();  // keeps the test short; the app never blocks
  }
  b.flushChecks();
  ASSERT_TRUE(b.divergence().has_value()) << "dt = 2 t_c must blow up within " << frames << " frames";
  const std::string message = b.divergence()->message;
  EXPECT_EQ(message.rfind("balls diverged by t = ", 0), 0u) << message;
  EXPECT_NE(message.find("spring-dashpot"), std::string::npos) << message;
  EXPECT_NE(message.find("symplectic-euler"), std::string::npos) << message;
  EXPECT_NE(message.find("dt = 0.004"), std::string::npos) << message;
  const double reportedAt = b.divergence()->time;
  EXPECT_LE(reportedAt, b.time());

  ASSERT_TRUE(b.recover()) << "a good state was judged before the blow-up";
  EXPECT_FALSE(b.divergence().has_value());
  EXPECT_FLOAT_EQ(b.params().dt, dt / 2);
  EXPECT_EQ(b.params().substeps, 8);
  EXPECT_LT(b.time(), reportedAt) << "resumes from a state judged good, before the bad one";
  EXPECT_TRUE(allFiniteInside(b));
}

TEST_F(BallsTest, RecoveryEqualsATwinRunBitForBit) {
  gl::GpuProfiler profiler;
  Balls b(shaders(), restingBlock(1e-4f)), twin(shaders(), restingBlock(1e-4f));
  placeOnTheFloor(b);
  placeOnTheFloor(twin);
  ASSERT_GT(b.count(), 20u);
  runFrames(b, 40, profiler);  // settling on the floor springs: good states are judged and kept
  ASSERT_FALSE(b.divergence().has_value()) << b.divergence()->message;
  const float dt = 4e-3f;  // twice t_c: each landing kicks the ball harder
  b.params().dt = dt;
  runFrames(b, 400, profiler);
  ASSERT_TRUE(b.divergence().has_value()) << "dt = 2 t_c on the floor springs must blow up";
  const double failedAt = b.divergence()->time;

  ASSERT_TRUE(b.recover());
  const double goodTime = b.time();
  EXPECT_LT(goodTime, failedAt);
  EXPECT_GE(goodTime, 40 * 4 * 1e-4 - 1e-9) << "the last good state is the newest one judged good";
  // The twin replays the run (40 frames of 0.1 ms steps, then 4 ms steps) to the good time.
  for (int i = 0; i < 40; ++i) twin.step(profiler);
  twin.params().dt = dt;
  while (twin.time() < goodTime - 1e-9) twin.step(profiler);
  ASSERT_EQ(twin.time(), goodTime);
  EXPECT_EQ(stateSet(b), stateSet(twin)) << "the restored state is the good one, bit for bit";

  // Both go on with the halved step (2 ms, 8 substeps) alike.
  EXPECT_FLOAT_EQ(b.params().dt, dt / 2);
  twin.params().dt = b.params().dt;
  twin.params().substeps = b.params().substeps;
  for (int i = 0; i < 4; ++i) {
    b.step(profiler);
    twin.step(profiler);
  }
  EXPECT_EQ(b.time(), twin.time());
  EXPECT_EQ(stateSet(b), stateSet(twin)) << "the recovered run goes on as the twin does, bit for bit";
}

TEST_F(BallsTest, WithoutAGoodStateRecoveryIsRefused) {
  Balls b(shaders(), restingBlock(1e-4f));
  EXPECT_FALSE(b.recover()) << "nothing diverged";
}
