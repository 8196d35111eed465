// The GPU step equals the CPU reference; nothing is lost or escapes; pistons and spinning
// obstacles keep every ball inside and the obstacle intact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>

#include "base/error.h"
#include "reference/balls_reference.h"
#include "sim/balls/balls.h"
#include "sim/water/water_init.h"
#include "support/balls_fixtures.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::balls;
using namespace tidepool::water;

namespace {

using BallsTest = test::GlTest;

// A dense, jumbled cloud: overlaps, wall contacts, random velocities.
void jumbled(std::vector<glm::vec4>& pos, std::vector<glm::vec4>& vel, const Params& p, int count) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> ux(p.domainMin.x, p.domainMax.x), uy(p.domainMin.y, p.domainMax.y),
      uz(p.domainMin.z, 0.2f), uv(-1.0f, 1.0f);
  for (int i = 0; i < count; ++i) {
    pos.emplace_back(ux(rng), uy(rng), uz(rng), 1.0f);
    vel.emplace_back(uv(rng), uv(rng), uv(rng), 0.0f);
  }
}

}  // namespace

// Each ball's index rides in its position's w, which every pass carries through untouched, so the
// GPU's cell order maps back to the CPU's whatever the step reordered: Verlet's first step sorts
// twice (for a(x0), then after the drift), and lastOrder() holds only the last sort.
TEST_F(BallsTest, GpuStepEqualsCpuReferenceForEveryContactLawAndIntegrator) {
  for (Contact contact : {Contact::SpringDashpot, Contact::Penalty, Contact::CudaSample})
    for (Integrator integrator : {Integrator::SymplecticEuler, Integrator::ExplicitEuler, Integrator::VelocityVerlet}) {
      SCOPED_TRACE(std::string(kContactNames[int(contact)]) + " / " + kIntegratorNames[int(integrator)]);
      Params p = test::emptyTank();
      p.contact = contact;
      p.integrator = integrator;
      p.friction = contact == Contact::SpringDashpot ? 0.3f : 0.0f;
      p.damping = 0.5f;
      std::vector<glm::vec4> pos, vel;
      jumbled(pos, vel, p, 600);
      for (std::size_t i = 0; i < pos.size(); ++i) pos[i].w = float(i);
      Balls gpu(shaders(), p);
      gpu.upload(pos, vel);
      reference::State cpu = reference::state(pos, vel);
      for (int n = 1; n <= 2; ++n) {  // Verlet's second step starts from the a its first one stored
        SCOPED_TRACE("step " + std::to_string(n));
        gpu.stepOnce();
        reference::step(cpu, p);
        const std::vector<glm::vec4> gx = gpu.downloadPositions();
        std::vector<unsigned> order;
        for (const glm::vec4& x : gx) order.push_back(unsigned(x.w));
        const reference::Gap gap = reference::gap(cpu, gx, gpu.downloadVelocities(), order);
        EXPECT_LT(gap.position, 1e-5 * 0.5) << "positions (relative to the 0.5 m domain)";
        EXPECT_LT(gap.velocity, 1e-5) << "velocities, relative";
      }
    }
}

// Euler keeps no accelerations and no order of the last step: 20 bytes per ball fewer. A live
// switch to velocity Verlet allocates them and steps as a model that started with Verlet does.
TEST_F(BallsTest, AccelerationsAndOrderAreAllocatedOnlyWhenUsed) {
  Params p = test::emptyTank();
  std::vector<glm::vec4> pos, vel;
  jumbled(pos, vel, p, 500);
  Balls euler(shaders(), p);
  euler.upload(pos, vel);
  euler.stepOnce();
  const std::size_t eulerBytes = euler.bytesPerBall();
  EXPECT_THROW(euler.lastOrder(), Error) << "no order kept without trackOrder()";
  euler.params().integrator = Integrator::VelocityVerlet;
  Params verletParams = p;
  verletParams.integrator = Integrator::VelocityVerlet;
  Balls verlet(shaders(), verletParams);
  verlet.upload(euler.downloadPositions(), euler.downloadVelocities());
  euler.stepOnce();
  verlet.stepOnce();
  EXPECT_EQ(euler.bytesPerBall(), eulerBytes + sizeof(glm::vec4)) << "the accelerations, one vec4 per ball";
  const std::vector<glm::vec4> a = euler.downloadPositions(), b = verlet.downloadPositions();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::vec4)), 0);
  euler.trackOrder(true);
  euler.stepOnce();
  EXPECT_EQ(euler.lastOrder().size(), pos.size());
}

TEST_F(BallsTest, NothingIsLostOrEscapesAndNothingIsNaN) {
  Params p = test::emptyTank();
  p.fill = Fill::Random;
  p.fillMin = p.domainMin;
  p.fillMax = p.domainMax;
  p.randomCount = int(water::fillCapacity(p));  // as crowded as a fill may be: 1325, close packed
  p.dt = 1e-3f;                                 // coarse on purpose
  Balls b(shaders(), p);
  gl::GpuProfiler profiler;
  for (int i = 0; i < 40; ++i) b.step(profiler);
  const Stats s = b.stats();
  EXPECT_EQ(s.count, std::size_t(p.randomCount));
  EXPECT_EQ(s.nonFinite, 0u);
  EXPECT_EQ(s.outside, 0u);
}

TEST_F(BallsTest, PistonPushesBallsWithoutLosingAny) {
  Params p = test::emptyTank();
  p.fill = Fill::Block;
  p.fillMin = p.domainMin;
  p.fillMax = glm::vec3(0.4f, 0.3f, 0.2f);
  p.pistonAxis = 1;  // the x max wall moves in to 60% of the width and back
  p.pistonTravel = 0.6f;
  p.pistonPeriod = 0.4f;
  p.substeps = 20;
  Balls b(shaders(), p);
  const std::size_t n = b.count();
  ASSERT_GT(n, 200u);
  gl::GpuProfiler profiler;
  float minWall = 1.0f;
  for (int frame = 0; frame < 50; ++frame) {  // 0.2 s: the wall goes all the way in
    b.step(profiler);
    minWall = std::min(minWall, b.wallMax().x);
    for (const glm::vec4& q : b.downloadPositions()) ASSERT_LE(q.x, b.wallMax().x + 1e-6f) << "frame " << frame;
  }
  EXPECT_LT(minWall, 0.2f);
  const Stats s = b.stats();
  EXPECT_EQ(s.count, n);
  EXPECT_EQ(s.nonFinite, 0u);
}

TEST_F(BallsTest, SpinningObstacleKeepsItsParticlesAndStirsTheWater) {
  Params p = test::emptyTank();
  p.domainMax = glm::vec3(0.6f, 0.6f, 0.4f);
  p.fill = Fill::Slab;
  p.slabHeight = 0.15f;
  ObstacleParams paddle;
  paddle.shape = Shape::Box;
  paddle.centre = glm::vec3(0.3f, 0.3f, 0.1f);
  paddle.size = glm::vec3(0.2f, 0.04f, 0.1f);
  paddle.spin = 6.0f;
  p.obstacles = {paddle};
  p.substeps = 25;
  Balls b(shaders(), p);
  ASSERT_GT(b.obstacleCount(), 50u);
  const std::vector<glm::vec4> before = b.obstacles().bodies().read<glm::vec4>(b.obstacleCount());
  gl::GpuProfiler profiler;
  for (int i = 0; i < 20; ++i) b.step(profiler);
  EXPECT_EQ(b.obstacles().bodies().read<glm::vec4>(b.obstacleCount()), before) << "built once, never rebuilt";
  // The water turns with the paddle: positive mean angular momentum about its axis.
  double lz = 0;
  const std::vector<glm::vec4> x = b.downloadPositions(), v = b.downloadVelocities();
  for (std::size_t i = 0; i < x.size(); ++i) {
    const glm::vec2 r = glm::vec2(x[i]) - glm::vec2(paddle.centre);
    lz += r.x * v[i].y - r.y * v[i].x;
  }
  EXPECT_GT(lz / double(x.size()), 1e-4);
  const Stats s = b.stats();
  EXPECT_EQ(s.nonFinite, 0u);
  EXPECT_EQ(s.outside, 0u);
}

TEST_F(BallsTest, TooManyBallsAreRefusedBeforeAllocating) {
  Params p;
  p.fill = Fill::Lattice;
  p.latticeCount = 2000;
  p.maxParticles = 1000;
  try {
    Balls b(shaders(), p);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("would make about 2000 balls, but at most 1000 fit (max_particles = 1000)"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(BallsTest, TapEmitsUpToItsMaximumAndEveryBallStaysInside) {
  Params p = test::emptyTank();
  p.tap = true;
  p.tapPosition = glm::vec3(0.03f, 0.15f, 0.3f);  // a jet from the side wall, away from its own splash
  p.tapDirection = glm::vec3(1.0f, 0.0f, 0.2f);
  p.tapSpeed = 2.0f;
  p.tapRadius = 0.08f;  // about 19 balls a layer, a layer every 17 ms
  p.tapMax = 300;
  p.dt = 5e-4f;
  p.substeps = 10;
  Balls b(shaders(), p);
  EXPECT_EQ(b.count(), 0u);
  gl::GpuProfiler profiler;
  std::size_t last = 0;
  for (int frame = 0; frame < 100; ++frame) {  // 0.5 s
    b.step(profiler);
    EXPECT_GE(b.count(), last) << "balls are only ever added";
    last = b.count();
  }
  EXPECT_EQ(b.count(), 300u);
  const Stats s = b.stats();
  EXPECT_EQ(s.count, 300u);
  EXPECT_EQ(s.nonFinite, 0u);
  EXPECT_EQ(s.outside, 0u);
  EXPECT_LT(s.maxOverlap, 0.5) << "layers are emitted one spacing apart";
  // (A jet pointing up falls back on its own nozzle: new layers then start inside old balls and
  // the contact law pushes them apart. The fountain scene lives with that.)
}

TEST_F(BallsTest, ObstacleEditedWhileRunningIsRebuilt) {
  Params p = test::emptyTank();
  p.fill = Fill::None;
  Balls b(shaders(), p);
  EXPECT_EQ(b.obstacleCount(), 0u);
  ObstacleParams sphere;  // added
  sphere.shape = Shape::Sphere;
  sphere.centre = glm::vec3(0.2f, 0.15f, 0.2f);
  sphere.size = glm::vec3(0.08f);
  b.params().obstacles = {sphere};
  b.stepOnce();
  const std::size_t small = b.obstacleCount();
  EXPECT_GT(small, 20u);
  b.params().obstacles[0].size = glm::vec3(0.12f);  // resized
  b.stepOnce();
  EXPECT_GT(b.obstacleCount(), small);
  b.params().obstacles.clear();  // removed
  b.stepOnce();
  EXPECT_EQ(b.obstacleCount(), 0u);
}

// The collide counts the balls into the next step's grid as it writes them (no count pass): the
// counts equal the CPU's histogram of the new positions and every slot in a cell is taken once. An
// upload at the same count must void the counts the last collide took: the model then steps as a
// new one made from the uploaded state does, bit for bit.
TEST_F(BallsTest, CountingInTheCollideTakesTheNextGridsCounts) {
  for (Integrator integrator : {Integrator::SymplecticEuler, Integrator::ExplicitEuler}) {
    SCOPED_TRACE(kIntegratorNames[int(integrator)]);
    Params p = test::emptyTank();
    p.integrator = integrator;
    std::vector<glm::vec4> pos, vel;
    jumbled(pos, vel, p, 900);
    Balls fused(shaders(), p), fresh(shaders(), p);
    fused.upload(pos, vel);
    for (int n = 1; n <= 12; ++n) fused.stepOnce();
    std::vector<glm::vec4> reversed = fused.downloadPositions(), v = fused.downloadVelocities();
    std::reverse(reversed.begin(), reversed.end());
    std::reverse(v.begin(), v.end());
    fused.upload(reversed, v);  // a new state of the same size
    fresh.upload(reversed, v);
    for (int n = 13; n <= 30; ++n) {
      fused.stepOnce();
      fresh.stepOnce();
    }
    const std::vector<glm::vec4> x = fused.downloadPositions();
    ASSERT_EQ(0, std::memcmp(x.data(), fresh.downloadPositions().data(), x.size() * sizeof(glm::vec4)));
    const std::vector<glm::vec4> u = fused.downloadVelocities();
    ASSERT_EQ(0, std::memcmp(u.data(), fresh.downloadVelocities().data(), u.size() * sizeof(glm::vec4)));

    const grid::UniformGrid& g = *fused.neighbourGrid();
    const std::vector<uint32_t> counts = g.cellCount().read<uint32_t>(g.cells());
    EXPECT_EQ(counts, grid::reference::histogram(g.shape(), x)) << "the counts the collide took";
    const std::vector<uint32_t> slots = g.indexInCell().read<uint32_t>(x.size());
    const std::vector<uint32_t> cells = g.particleCell().read<uint32_t>(x.size());
    std::vector<std::vector<bool>> taken(g.cells());
    for (std::size_t c = 0; c < counts.size(); ++c) taken[c].resize(counts[c]);
    for (std::size_t i = 0; i < x.size(); ++i) {
      const uint32_t cell = grid::reference::cellOf(g.shape(), glm::vec3(x[i]));
      ASSERT_EQ(cells[i], cell) << "the cell the collide stored for ball " << i;
      ASSERT_LT(slots[i], counts[cell]) << "ball " << i;
      ASSERT_FALSE(taken[cell][slots[i]]) << "slot taken twice in cell " << cell;
      taken[cell][slots[i]] = true;
    }
  }
}
