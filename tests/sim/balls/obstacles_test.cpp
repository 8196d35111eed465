// Several obstacles, each moving rigidly (sim/water/obstacles.h): the shipped scene's obstacles
// keep their particles and shape while they turn and travel, the GPU places them where the CPU
// pose says and with that pose's velocity, one GPU step among moving obstacles equals the CPU
// reference, a moving obstacle pushes the water its way without losing a ball, and obstacles are
// added, removed, moved and turned while running.
#include <gtest/gtest.h>

#include <random>

#include "reference/balls_reference.h"
#include "scene/balls_stage.h"
#include "sim/balls/balls.h"
#include "support/balls_fixtures.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::balls;
using namespace tidepool::water;

namespace {

class ObstacleMotion : public test::GlTest {};

std::vector<glm::vec4> placed(const Balls& b) { return b.obstacles().placed().read<glm::vec4>(b.obstacleCount()); }

// Every particle of obstacle k where its pose puts its own-frame position, and (so its shape is
// kept) as far from a partner particle as in the own frame.
void expectRigid(const Balls& b, const std::vector<glm::vec4>& world) {
  const Obstacles& obs = b.obstacles();
  for (std::size_t k = 0; k < obs.size(); ++k) {
    SCOPED_TRACE(testing::Message() << "obstacle " << k);
    const ObstacleBody& body = obs.body(k);
    const std::size_t n = body.particles.size();
    double worstPlace = 0, worstDistance = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const glm::vec4 q = world[body.first + i];
      ASSERT_EQ(q.w, float(k)) << "each particle carries its obstacle's index";
      const glm::vec3 expected = obs.pose(k).place(glm::vec3(body.particles[i]));
      worstPlace = std::max(worstPlace, double(glm::length(glm::vec3(q) - expected)));
      for (const std::size_t j : {(i * 7 + 3) % n, n - 1 - i}) {
        const float before = glm::length(glm::vec3(body.particles[i]) - glm::vec3(body.particles[j]));
        const float now = glm::length(glm::vec3(q) - glm::vec3(world[body.first + j]));
        worstDistance = std::max(worstDistance, double(std::abs(now - before)));
      }
    }
    // fp32 about 1 m from the origin: a few ulps (6e-8 m) per operation.
    EXPECT_LT(worstPlace, 1e-6);
    EXPECT_LT(worstDistance, 1e-6);
  }
}

}  // namespace

TEST_F(ObstacleMotion, SceneObstaclesKeepTheirParticlesAndShapeWhileTurningAndTravelling) {
  Params p = ballsParams(loadScene(resolveScenePath("obstacles")));
  ASSERT_EQ(p.obstacles.size(), 3u);
  ASSERT_NE(p.obstacles[1].spin, 0.0f);
  ASSERT_NE(p.obstacles[2].path.kind, PathKind::None);
  p.radius = 0.02f;  // a few thousand balls for llvmpipe, falling on all three; no tap (a fixed count)
  p.fillMin = glm::vec3(0.05f, 0.05f, 0.6f);
  p.fillMax = glm::vec3(0.95f, 0.95f, 0.95f);
  p.tap = false;
  p.dt = 1e-3f;
  p.contactTime = 0.01f;
  Balls b(shaders(), p);
  const std::size_t water = b.count();
  ASSERT_GT(water, 1000u);
  std::vector<std::size_t> counts;
  for (std::size_t k = 0; k < 3; ++k) counts.push_back(b.obstacles().body(k).particles.size());
  for (std::size_t n : counts) EXPECT_GT(n, 20u);
  const std::vector<glm::vec4> start = placed(b);
  expectRigid(b, start);
  std::vector<double> fastest(3, 0.0);  // m/s, over the run
  for (int round = 0; round < 3; ++round) {
    for (int i = 0; i < 200; ++i) b.stepOnce();
    SCOPED_TRACE(testing::Message() << "t = " << b.time());
    const std::vector<glm::vec4> before = placed(b);
    const std::vector<ObstaclePose> poses = {b.obstacles().pose(0), b.obstacles().pose(1), b.obstacles().pose(2)};
    expectRigid(b, before);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(b.obstacles().body(k).particles.size(), counts[k]);
    // One step on, each particle moved by its pose's velocity (to the step's O(dt) and to fp32).
    b.stepOnce();
    const std::vector<glm::vec4> after = placed(b);
    for (std::size_t k = 0; k < 3; ++k) {
      const ObstacleBody& body = b.obstacles().body(k);
      double worst = 0;
      for (std::size_t i = body.first; i < body.first + body.particles.size(); ++i) {
        const glm::vec3 moved = (glm::vec3(after[i]) - glm::vec3(before[i])) / p.dt;
        const glm::vec3 v = poses[k].velocityAt(glm::vec3(before[i]));
        worst = std::max(worst, double(glm::length(moved - v)));
        fastest[k] = std::max(fastest[k], double(glm::length(v)));
      }
      EXPECT_LT(worst, 2e-3) << "obstacle " << k << ", speeds up to " << fastest[k] << " m/s";
    }
  }
  EXPECT_EQ(fastest[0], 0.0) << "the cup stands still";
  EXPECT_GT(fastest[1], 0.1) << "the helix turns";
  EXPECT_GT(fastest[2], 0.1) << "the sphere swings";
  const std::vector<glm::vec4> end = placed(b);
  EXPECT_EQ(end[b.obstacles().body(0).first], start[b.obstacles().body(0).first]) << "the cup stays put";
  EXPECT_GT(glm::length(glm::vec3(end[b.obstacles().body(2).first] - start[b.obstacles().body(2).first])), 0.05f)
      << "the sphere travelled";
  const Stats s = b.stats();
  EXPECT_EQ(s.count, water);
  EXPECT_EQ(s.nonFinite, 0u);
  EXPECT_EQ(s.outside, 0u);
}

TEST_F(ObstacleMotion, GpuStepAmongMovingObstaclesEqualsTheCpuReference) {
  for (Contact contact : {Contact::SpringDashpot, Contact::CudaSample, Contact::Penalty}) {
    SCOPED_TRACE(kContactNames[int(contact)]);
    Params p = test::emptyTank();
    p.contact = contact;
    p.friction = contact == Contact::SpringDashpot ? 0.3f : 0.0f;
    ObstacleParams box, sphere;  // a tumbling box and a sphere spinning on a circle
    box.shape = Shape::Box;
    box.centre = glm::vec3(0.1f, 0.15f, 0.1f);
    box.size = glm::vec3(0.06f, 0.03f, 0.05f);
    box.orientation = glm::vec3(20.0f, 0.0f, 35.0f);
    box.spin = 5.0f;
    box.spinAxis = glm::vec3(1.0f, 1.0f, 0.0f);
    sphere.shape = Shape::Sphere;
    sphere.centre = glm::vec3(0.28f, 0.15f, 0.1f);
    sphere.size = glm::vec3(0.06f);
    sphere.spin = -3.0f;
    sphere.path.kind = PathKind::Circle;
    sphere.path.amplitude = glm::vec3(0.04f, 0.05f, 0.02f);
    sphere.path.period = 0.5f;
    sphere.path.phase = 30.0f;
    p.obstacles = {box, sphere};
    Balls gpu(shaders(), p);
    // Balls all over and into the obstacles, moving every way.
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> ux(0.0f, 0.4f), uy(0.05f, 0.25f), uz(0.0f, 0.2f), uv(-1.0f, 1.0f);
    std::vector<glm::vec4> pos, vel;
    for (int i = 0; i < 500; ++i) {
      pos.emplace_back(ux(rng), uy(rng), uz(rng), 1.0f);
      vel.emplace_back(uv(rng), uv(rng), uv(rng), 0.0f);
    }
    gpu.upload(pos, vel);
    gpu.trackOrder(true);
    gpu.stepOnce();
    // The reference sees the obstacle particles where the GPU placed them, moving as their pose says.
    std::vector<reference::Fixed> fixed;
    const std::vector<glm::vec4> world = placed(gpu);
    for (const glm::vec4& q : world)
      fixed.push_back({glm::dvec3(glm::vec3(q)), glm::dvec3(gpu.obstacles().pose(std::size_t(q.w)).velocityAt(q))});
    reference::State cpu = reference::state(pos, vel);
    reference::step(cpu, p, fixed);
    const reference::Gap gap = reference::gap(cpu, gpu.downloadPositions(), gpu.downloadVelocities(), gpu.lastOrder());
    double obstacleContacts = 0;
    for (std::size_t i = 0; i < pos.size(); ++i)
      for (const reference::Fixed& f : fixed) obstacleContacts += glm::length(cpu.x[i] - f.x) < 2.0 * p.radius;
    EXPECT_GT(obstacleContacts, 200) << "many balls touch the obstacles";
    EXPECT_LT(gap.position, 1e-5 * 0.5) << "positions (relative to the 0.5 m domain)";
    EXPECT_LT(gap.velocity, 1e-5) << "velocities, relative";
  }
}

namespace {

struct Push {
  double momentum = 0, meanX = 0;  // of the water: Σ v.x, mean x
  Stats stats;
};

// A plate standing in a pool, moving along x with `phase` (0: +x first, 180: −x first), or still.
Push pushWater(gl::ShaderLibrary& shaders, bool moving, float phase,
               Integrator integrator = Integrator::SymplecticEuler) {
  Params p;
  p.integrator = integrator;
  p.radius = 0.01f;
  p.domainMax = glm::vec3(0.6f, 0.3f, 0.3f);
  p.fill = Fill::Slab;
  p.slabHeight = 0.1f;
  p.dt = 5e-4f;
  p.contactTime = 0.005f;
  p.restitution = 0.3f;
  ObstacleParams plate;
  plate.shape = Shape::Box;
  plate.centre = glm::vec3(0.3f, 0.15f, 0.07f);
  plate.size = glm::vec3(0.02f, 0.12f, 0.07f);
  if (moving) {
    plate.path.kind = PathKind::Oscillate;
    plate.path.amplitude = glm::vec3(0.08f, 0.0f, 0.0f);  // 0.5 m/s at t = 0
    plate.path.period = 1.0f;
    plate.path.phase = phase;
  }
  p.obstacles = {plate};
  Balls b(shaders, p);
  for (int i = 0; i < 300; ++i) b.stepOnce();  // 0.15 s: still going its first way
  Push out;
  const std::vector<glm::vec4> x = b.downloadPositions(), v = b.downloadVelocities();
  for (std::size_t i = 0; i < x.size(); ++i) {
    out.momentum += v[i].x;
    out.meanX += x[i].x / double(x.size());
  }
  out.stats = b.stats();
  return out;
}

}  // namespace

TEST_F(ObstacleMotion, MovingObstaclePushesTheWaterItsWayAndLosesNoBall) {
  const Push still = pushWater(shaders(), false, 0.0f);
  const Push forward = pushWater(shaders(), true, 0.0f);
  const Push backward = pushWater(shaders(), true, 180.0f);
  const Push verlet = pushWater(shaders(), true, 0.0f, Integrator::VelocityVerlet);  // forces at t + dt
  std::printf(
      "water momentum x: still %.4g, forward %.4g, backward %.4g, forward (Verlet) %.4g; mean x %.5f %.5f %.5f\n",
      still.momentum, forward.momentum, backward.momentum, verlet.momentum, still.meanX, forward.meanX, backward.meanX);
  EXPECT_GT(forward.momentum, 0.0);
  EXPECT_LT(backward.momentum, 0.0);
  EXPECT_LT(std::abs(still.momentum), 0.2 * forward.momentum);
  EXPECT_LT(std::abs(still.momentum), 0.2 * -backward.momentum);
  EXPECT_GT(forward.meanX, still.meanX + 1e-4);
  EXPECT_LT(backward.meanX, still.meanX - 1e-4);
  EXPECT_NEAR(verlet.momentum, forward.momentum, 0.2 * forward.momentum);
  for (const Push* run : {&still, &forward, &backward, &verlet}) {
    EXPECT_EQ(run->stats.count, still.stats.count);
    EXPECT_EQ(run->stats.nonFinite, 0u);
    EXPECT_EQ(run->stats.outside, 0u);
  }
}

TEST_F(ObstacleMotion, AddedRemovedMovedAndTurnedWhileRunningWithCountsKept) {
  Params p;
  p.radius = 0.02f;
  p.domainMax = glm::vec3(0.6f);
  p.fill = Fill::Block;
  p.fillMin = glm::vec3(0.0f, 0.0f, 0.4f);
  p.fillMax = glm::vec3(0.6f, 0.6f, 0.6f);
  p.dt = 1e-3f;
  ObstacleParams sphere, box, cup;
  sphere.shape = Shape::Sphere;
  sphere.centre = glm::vec3(0.15f, 0.15f, 0.15f);
  sphere.size = glm::vec3(0.08f);
  box.shape = Shape::Box;
  box.centre = glm::vec3(0.45f, 0.15f, 0.15f);
  box.size = glm::vec3(0.1f, 0.05f, 0.08f);
  cup.shape = Shape::Cup;
  cup.centre = glm::vec3(0.3f, 0.42f, 0.02f);
  cup.size = glm::vec3(0.15f, 0.15f, 0.2f);
  p.obstacles = {sphere, box};
  Balls b(shaders(), p);
  const std::size_t water = b.count();
  const Obstacles& obs = b.obstacles();
  const std::size_t nSphere = obs.body(0).particles.size(), nBox = obs.body(1).particles.size();
  const unsigned idSphere = obs.body(0).id, idBox = obs.body(1).id;
  EXPECT_EQ(b.obstacleCount(), nSphere + nBox);
  auto indices = [&] {
    std::vector<float> w;
    for (const glm::vec4& q : obs.bodies().read<glm::vec4>(b.obstacleCount())) w.push_back(q.w);
    return w;
  };

  b.params().obstacles.push_back(cup);  // added
  b.stepOnce();
  ASSERT_EQ(obs.size(), 3u);
  const std::size_t nCup = obs.body(2).particles.size();
  const unsigned idCup = obs.body(2).id;
  EXPECT_GT(nCup, 50u);
  EXPECT_EQ(b.obstacleCount(), nSphere + nBox + nCup);
  EXPECT_EQ(obs.body(0).id, idSphere) << "the others are not rebuilt";
  EXPECT_EQ(obs.body(1).id, idBox);
  EXPECT_EQ(b.count(), water);

  b.params().obstacles.erase(b.params().obstacles.begin() + 1);  // the box removed
  b.stepOnce();
  ASSERT_EQ(obs.size(), 2u);
  EXPECT_EQ(b.obstacleCount(), nSphere + nCup);
  EXPECT_EQ(obs.body(0).id, idSphere);
  EXPECT_EQ(obs.body(1).id, idCup) << "the cup keeps its particles, now as obstacle 1";
  std::vector<float> expected(nSphere, 0.0f);
  expected.resize(nSphere + nCup, 1.0f);
  EXPECT_EQ(indices(), expected);
  expectRigid(b, placed(b));

  b.params().obstacles[0].centre += glm::vec3(0.05f, 0.0f, 0.02f);  // moved and turned: placed anew
  b.params().obstacles[0].orientation = glm::vec3(10.0f, 0.0f, 40.0f);
  b.stepOnce();
  EXPECT_EQ(obs.body(0).id, idSphere);
  EXPECT_EQ(obs.pose(0).centre, sphere.centre + glm::vec3(0.05f, 0.0f, 0.02f));
  expectRigid(b, placed(b));

  b.params().obstacles.push_back(cup);  // a mesh that is not there: refused, the list as it was
  b.params().obstacles.back().shape = Shape::Mesh;
  b.params().obstacles.back().mesh = "no-such-mesh";
  b.stepOnce();
  EXPECT_EQ(b.params().obstacles.size(), 2u);
  EXPECT_EQ(obs.size(), 2u);
  EXPECT_EQ(b.obstacleError().rfind("obstacles[2] not changed: mesh 'no-such-mesh' not found", 0), 0u)
      << b.obstacleError();

  b.params().obstacles.clear();
  for (int i = 0; i < 40; ++i) b.stepOnce();
  EXPECT_EQ(b.obstacleCount(), 0u);
  const Stats s = b.stats();
  EXPECT_EQ(s.count, water) << "no ball lost through all of it";
  EXPECT_EQ(s.nonFinite, 0u);
  EXPECT_EQ(s.outside, 0u);
}
