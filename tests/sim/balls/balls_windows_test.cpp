// Balls whose vec4 arrays pass one storage block: with the limit lowered to 256 KiB,
// windows hold 16384 balls and the collide's windows 8192 (plus the balls in reach of them), so
// these 40,000 balls step in several windows per pass. A deterministic run must be the unwindowed
// one bit for bit, for both integrators, both reorders and with an obstacle, and so must its
// statistics and loads; a scene whose neighbours cannot fit a window is refused with the numbers.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "base/error.h"
#include "gl/window.h"
#include "sim/balls/balls.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::balls;
using namespace tidepool::water;

namespace {

constexpr std::size_t kLimit = 256 << 10;

class BallsWindows : public test::GlTest {
 protected:
  void TearDown() override { gl::overrideStorageBlockBytes(0); }
};

// 40,000 balls of r = 5 mm jumbled through a 0.4 x 0.3 x 0.5 m box: 60,000 cells of 2r.
Params box() {
  Params p;
  p.radius = 0.005f;
  p.domainMin = glm::vec3(0.0f);
  p.domainMax = glm::vec3(0.4f, 0.3f, 0.5f);
  p.fill = Fill::Random;
  p.randomCount = 40000;
  p.fillMin = p.domainMin;
  p.fillMax = p.domainMax;
  p.dt = 2e-4f;
  p.contactTime = 0.004f;
  p.deterministic = true;
  return p;
}

struct Outcome {
  std::vector<glm::vec4> x, v;
  Stats stats;
  std::size_t windows = 0;
  Loads loads;  // with force probes listed
};

Outcome run(gl::ShaderLibrary& shaders, const Params& p, std::size_t limit, int steps) {
  gl::overrideStorageBlockBytes(limit);
  Balls b(shaders, p);
  for (int n = 0; n < steps; ++n) b.stepOnce();
  Outcome r{b.downloadPositions(), b.downloadVelocities(), b.stats(), b.collideWindows(), b.loads()};
  gl::overrideStorageBlockBytes(0);
  return r;
}

void expectSame(const Outcome& a, const Outcome& b) {
  ASSERT_EQ(a.x.size(), b.x.size());
  EXPECT_EQ(0, std::memcmp(a.x.data(), b.x.data(), a.x.size() * sizeof(glm::vec4))) << "positions";
  EXPECT_EQ(0, std::memcmp(a.v.data(), b.v.data(), a.v.size() * sizeof(glm::vec4))) << "velocities";
  EXPECT_EQ(a.stats.kinetic, b.stats.kinetic);
  EXPECT_EQ(a.stats.meanOverlap, b.stats.meanOverlap);
  EXPECT_EQ(a.stats.maxOverlap, b.stats.maxOverlap);
  EXPECT_EQ(a.stats.contactsPerBall, b.stats.contactsPerBall);
  EXPECT_EQ(a.stats.front, b.stats.front);
  // Bit for bit (NaN where none was measured).
  auto same = [](const Load& x, const Load& y) { return std::memcmp(&x, &y, sizeof(Load)) == 0; };
  ASSERT_EQ(a.loads.obstacles.size(), b.loads.obstacles.size());
  for (std::size_t k = 0; k < a.loads.obstacles.size(); ++k)
    EXPECT_TRUE(same(a.loads.obstacles[k], b.loads.obstacles[k])) << "obstacle " << k;
  EXPECT_TRUE(same(a.loads.walls[4], b.loads.walls[4])) << "the floor";
}

}  // namespace

TEST_F(BallsWindows, WindowedStepsEqualOneBlockBitForBit) {
  for (Integrator integrator : {Integrator::SymplecticEuler, Integrator::VelocityVerlet}) {
    SCOPED_TRACE(kIntegratorNames[int(integrator)]);
    Params p = box();
    p.integrator = integrator;
    const Outcome whole = run(shaders(), p, 0, 6), windowed = run(shaders(), p, kLimit, 6);
    EXPECT_EQ(whole.windows, 1u);
    EXPECT_GE(windowed.windows, 5u) << "40,000 balls in windows of 8192 and their neighbours";
    expectSame(whole, windowed);
    EXPECT_GT(windowed.stats.contactsPerBall, 0.5) << "a jumbled box: the balls touch";
    EXPECT_EQ(windowed.stats.nonFinite, 0u);
  }
}

// With an obstacle, the next grid's count and the loads (their work groups' partials bound a
// window at a time).
TEST_F(BallsWindows, ObstacleCountAndLoadsPassInWindows) {
  Params p = box();
  ObstacleParams paddle;
  paddle.shape = Shape::Box;
  paddle.centre = glm::vec3(0.2f, 0.15f, 0.25f);
  paddle.size = glm::vec3(0.2f, 0.04f, 0.1f);
  paddle.spin = 6.0f;
  p.obstacles = {paddle};
  p.probes = {{.kind = ProbeKind::Force, .obstacle = 0}, {.kind = ProbeKind::Force, .wall = ProbeWall::MinZ}};
  const Outcome whole = run(shaders(), p, 0, 5), windowed = run(shaders(), p, kLimit, 5);
  expectSame(whole, windowed);
  EXPECT_GT(glm::length(windowed.loads.obstacles.at(0).force), 0.0) << "the paddle is pushed";
  EXPECT_LT(windowed.loads.walls[4].force.z, 0.0) << "the floor is pushed down";
}

// Two layers of cells, full of balls: every ball is within a plane and a row of every other, so
// no window of 4096 balls has its neighbours within 16384.
TEST_F(BallsWindows, NeighboursPastOneWindowAreRefused) {
  Params p = box();
  p.domainMax = glm::vec3(1.8f, 1.8f, 0.02f);
  p.fillMax = p.domainMax;
  p.randomCount = 50000;
  gl::overrideStorageBlockBytes(kLimit);
  try {
    Balls b(shaders(), p);
    b.stepOnce();
    FAIL() << "expected an error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("over the storage-block limit of 16384 balls"), std::string::npos) << what;
    EXPECT_NE(what.find("raise particles.radius"), std::string::npos) << what;
  }
}

TEST_F(BallsWindows, WordsPastOneBlockAreRefusedBeforeAllocating) {
  Params p = box();
  p.randomCount = 70000;  // 280,000 bytes per word array: over 256 KiB
  gl::overrideStorageBlockBytes(kLimit);
  try {
    Balls b(shaders(), p);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "but at most 65536 fit (the storage-block limit, 256 KiB per array of 4 B per ball)"),
              std::string::npos)
        << e.what();
  }
}
