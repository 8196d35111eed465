// Failing loudly (issue 10): a balls run past its stability limit is caught by the non-blocking
// watch, reported with the time, contact law, integrator and time step, and recovered from the
// last good state with half the time step; a stable run is never flagged.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/balls/balls.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::balls;

namespace {

class BallsDivergence : public test::GlTest {};

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

}  // namespace

TEST_F(BallsDivergence, StableRunsAreNeverFlagged) {
  Balls b(shaders(), restingBlock(1e-4f));
  gl::GpuProfiler profiler;
  for (int i = 0; i < 120; ++i) b.step(profiler);
  b.flushChecks();
  EXPECT_FALSE(b.divergence().has_value()) << b.divergence()->message;
}

TEST_F(BallsDivergence, BlowUpIsReportedAndRecoveredWithHalfTheStep) {
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

TEST_F(BallsDivergence, WithoutAGoodStateRecoveryIsRefused) {
  Balls b(shaders(), restingBlock(1e-4f));
  EXPECT_FALSE(b.recover()) << "nothing diverged";
}
