// The balls' loads on the walls and the obstacles (shaders/balls/loads.comp, force probes): one
// step's equal the CPU reference's sums of the contact accelerations (balls_reference.h) for every
// contact law and integrator, and measuring them changes nothing in the run.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "reference/balls_reference.h"
#include "sim/balls/balls.h"
#include "support/balls_fixtures.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::balls;
using namespace tidepool::water;

namespace {

using BallsLoads = test::GlTest;
constexpr double kRho = 1000.0;  // the balls' rest density

// Force probes on every wall and on each of `obstacles` obstacles.
std::vector<ProbeParams> everyLoad(std::size_t obstacles) {
  std::vector<ProbeParams> probes;
  for (ProbeWall w :
       {ProbeWall::MinX, ProbeWall::MaxX, ProbeWall::MinY, ProbeWall::MaxY, ProbeWall::MinZ, ProbeWall::MaxZ})
    probes.push_back({.kind = ProbeKind::Force, .wall = w});
  for (std::size_t k = 0; k < obstacles; ++k) probes.push_back({.kind = ProbeKind::Force, .obstacle = int(k)});
  return probes;
}

// The step tests' tank with a box turned on two axes and a sphere, spinning and circling unless
// `still`, and force probes on everything.
Params tankWithTwoObstacles(bool still) {
  Params p = test::emptyTank();
  ObstacleParams box, sphere;
  box.shape = Shape::Box;
  box.centre = glm::vec3(0.1f, 0.15f, 0.1f);
  box.size = glm::vec3(0.06f, 0.03f, 0.05f);
  box.orientation = glm::vec3(20.0f, 0.0f, 35.0f);
  sphere.shape = Shape::Sphere;
  sphere.centre = glm::vec3(0.28f, 0.15f, 0.1f);
  sphere.size = glm::vec3(0.06f);
  if (!still) {
    box.spin = 5.0f;
    box.spinAxis = glm::vec3(1.0f, 1.0f, 0.0f);
    sphere.spin = -3.0f;
    sphere.path.kind = PathKind::Circle;
    sphere.path.amplitude = glm::vec3(0.04f, 0.05f, 0.02f);
    sphere.path.period = 0.5f;
  }
  p.obstacles = {box, sphere};
  p.probes = everyLoad(2);
  return p;
}

// Balls all over the tank's lower part and into the obstacles, moving every way.
void jumbled(std::vector<glm::vec4>& pos, std::vector<glm::vec4>& vel) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> ux(0.0f, 0.4f), uy(0.0f, 0.3f), uz(0.0f, 0.2f), uv(-1.0f, 1.0f);
  for (int i = 0; i < 500; ++i) {
    pos.emplace_back(ux(rng), uy(rng), uz(rng), 1.0f);
    vel.emplace_back(uv(rng), uv(rng), uv(rng), 0.0f);
  }
}

}  // namespace

// The reference sees the obstacle particles where the GPU placed them for the step's forces (at
// t, or at t + dt for Verlet), at the balls' state then (the step's start, or Verlet's drifted
// positions and half-step velocities). Verlet's obstacles stand still: its first step evaluates a
// at t before the drift, and the reference has one set of particles. The GPU's float sums are
// within 1.7e-6 of the double ones (forces and torques, relative); asserted 5e-6.
TEST_F(BallsLoads, OneStepsLoadsEqualTheReferencesForEveryContactLawAndIntegrator) {
  for (Contact contact : {Contact::SpringDashpot, Contact::Penalty, Contact::CudaSample})
    for (Integrator integrator : {Integrator::SymplecticEuler, Integrator::ExplicitEuler, Integrator::VelocityVerlet}) {
      SCOPED_TRACE(std::string(kContactNames[int(contact)]) + " / " + kIntegratorNames[int(integrator)]);
      const bool verlet = integrator == Integrator::VelocityVerlet;
      Params p = tankWithTwoObstacles(verlet);
      p.contact = contact;
      p.integrator = integrator;
      p.friction = contact == Contact::SpringDashpot ? 0.3f : 0.0f;
      Balls gpu(shaders(), p);
      std::vector<glm::vec4> pos, vel;
      jumbled(pos, vel);
      gpu.upload(pos, vel);
      EXPECT_TRUE(std::isnan(gpu.loads().obstacles.at(0).force.x)) << "no step yet";
      gpu.stepOnce();
      const Loads got = gpu.loads();

      std::vector<reference::Fixed> fixed;
      for (const glm::vec4& q : gpu.obstacles().placed().read<glm::vec4>(gpu.obstacleCount())) {
        const std::size_t k = std::size_t(q.w);
        fixed.push_back({glm::dvec3(glm::vec3(q)), glm::dvec3(gpu.obstacles().pose(k).velocityAt(q)), k});
      }
      const std::vector<glm::dvec3> centres = {glm::dvec3(gpu.obstacles().pose(0).centre),
                                               glm::dvec3(gpu.obstacles().pose(1).centre)};
      reference::State cpu = reference::state(pos, vel);
      if (verlet) reference::drift(cpu, p, fixed);
      const reference::Loads want = reference::loads(cpu, p, fixed, centres, gpu.mass());

      ASSERT_EQ(got.obstacles.size(), 2u);
      for (std::size_t k = 0; k < 2; ++k) {
        SCOPED_TRACE("obstacle " + std::to_string(k));
        const double force = glm::length(want.force[k]), torque = glm::length(want.torque[k]);
        ASSERT_GT(force, 0.0) << "balls touch it";
        std::printf("obstacle %zu: |F| %.4g N, error %.2g; |T| %.4g N m, error %.2g\n", k, force,
                    glm::length(got.obstacles[k].force - want.force[k]) / force, torque,
                    glm::length(got.obstacles[k].torque - want.torque[k]) / torque);
        EXPECT_LT(glm::length(got.obstacles[k].force - want.force[k]), 5e-6 * force);
        EXPECT_LT(glm::length(got.obstacles[k].torque - want.torque[k]), 5e-6 * torque);
      }
      for (std::size_t w = 0; w < kWalls; ++w) {
        SCOPED_TRACE("wall " + std::to_string(w));
        const double on = got.walls[w].force[int(w / 2)];
        if (contact == Contact::CudaSample) {
          EXPECT_TRUE(std::isnan(on)) << "the sample's walls clamp: no force to measure";
          continue;
        }
        EXPECT_NEAR(on, want.walls[w], 5e-6 * std::abs(want.walls[w])) << "want " << want.walls[w];
      }
      if (contact != Contact::CudaSample) EXPECT_NE(want.walls[4], 0.0) << "balls touch the floor";
    }
}

// The loads pass reads the state and writes only its partials: a run with every load measured
// is the run without, bit for bit.
TEST_F(BallsLoads, MeasuringTheLoadsChangesNothingInTheRun) {
  Params p = tankWithTwoObstacles(false);
  p.deterministic = true;
  std::vector<glm::vec4> pos, vel;
  jumbled(pos, vel);
  std::vector<glm::vec4> x[2], v[2];
  for (int measured = 0; measured < 2; ++measured) {
    if (measured == 0)
      p.probes.clear();
    else
      p.probes = everyLoad(2);
    Balls b(shaders(), p);
    b.upload(pos, vel);
    for (int n = 0; n < 20; ++n) b.stepOnce();
    x[measured] = b.downloadPositions();
    v[measured] = b.downloadVelocities();
  }
  ASSERT_EQ(x[0].size(), x[1].size());
  EXPECT_EQ(0, std::memcmp(x[0].data(), x[1].data(), x[0].size() * sizeof(glm::vec4)));
  EXPECT_EQ(0, std::memcmp(v[0].data(), v[1].data(), v[0].size() * sizeof(glm::vec4)));
}

namespace {

// A tank 0.2 × 0.1 m with a slab of balls settled for 1.5 s, and the mean of every step's loads over
// the next half second, with the balls' total weight and the height their rest volume fills.
struct Settled {
  Loads mean;
  double weight = 0, height = 0;
};
Settled settle(gl::ShaderLibrary& shaders, Params p) {
  Balls b(shaders, p);
  while (b.time() < 1.5) b.stepOnce();
  Settled out;
  out.mean = Loads::unmeasured(p.obstacles.size());
  for (Load& l : out.mean.walls) l.force = glm::dvec3(0.0);
  for (Load& l : out.mean.obstacles) l = Load{};
  int steps = 0;
  for (; b.time() < 2.0; ++steps) {
    b.stepOnce();
    const Loads l = b.loads();
    for (std::size_t w = 0; w < kWalls; ++w) out.mean.walls[w].force += l.walls[w].force;
    for (std::size_t k = 0; k < l.obstacles.size(); ++k) out.mean.obstacles[k].force += l.obstacles[k].force;
  }
  for (Load& l : out.mean.walls) l.force /= steps;
  for (Load& l : out.mean.obstacles) l.force /= steps;
  const double volume = b.count() * double(volumePerParticle(b.radius(), Params::kPacking));
  out.weight = kRho * volume * 9.81;  // ρ0 = 1000 kg/m³, the default
  out.height = volume / (0.2 * 0.1);
  return out;
}

Params settlingTank(float radius, float fill) {
  Params p;
  p.radius = radius;
  p.domainMax = glm::vec3(0.2f, 0.1f, 0.3f);
  p.fill = Fill::Slab;
  p.slabHeight = fill;
  p.dt = 0.04f * radius;  // 20 steps per contact
  p.contactTime = 0.8f * radius;
  p.probes = everyLoad(0);
  return p;
}

}  // namespace

// 228 balls of r = 1 cm settle into five layers: the floor carries their weight within 0.1%
// (measured −0.002% to +0.004%: at rest the contacts balance gravity). The side walls are pushed outwards,
// but by no hydrostatic law: a pile of balls at rest is a crystal that carries sideways 0.36 to
// 1.39 times ρ g H² w / 2 depending on its size and lattice (docs/WATER.md, "Probes").
TEST_F(BallsLoads, ARestingPilesFloorCarriesItsWeight) {
  const Settled s = settle(shaders(), settlingTank(0.01f, 0.1f));
  const double floor = -s.mean.walls[4].force.z;
  std::printf("floor %.4f N, weight %.4f N (%+.3f%%)\n", floor, s.weight, 100 * (floor / s.weight - 1));
  EXPECT_NEAR(floor, s.weight, 0.001 * s.weight);
  EXPECT_EQ(s.mean.walls[5].force.z, 0.0) << "the lid: no ball there";
  const double width[4] = {0.1, 0.1, 0.2, 0.2};
  for (int w = 0; w < 4; ++w) {
    const double got = s.mean.walls[std::size_t(w)].force[w / 2], outward = w % 2 == 0 ? -got : got;
    const double thrust = kRho * 9.81 * s.height * s.height * width[w] / 2;
    std::printf("wall %d: %.3f N, %.2f of rho g H^2 w / 2\n", w, outward, outward / thrust);
    EXPECT_GT(outward, 0.0) << "wall " << w;
  }
}

// A box of half extent 2.5 cm held 3.6 cm under 12.7 cm of resting balls (r = 5 mm) is pressed
// down, by 2.46 to 2.69 N over runs (the packing differs from run to run), where water would lift
// it by ρ g V = 1.23 N: the balls above rest on it as sand would (docs/WATER.md, "Probes").
// The floor and the box carry all the balls' weight between them, within 0.2%.
TEST_F(BallsLoads, AHeldBoxUnderRestingBallsIsPressedDownNotLifted) {
  Params p = settlingTank(0.005f, 0.15f);
  ObstacleParams box;
  box.shape = Shape::Box;
  box.centre = glm::vec3(0.1f, 0.05f, 0.06f);
  box.size = glm::vec3(0.025f);
  p.obstacles = {box};
  p.probes = everyLoad(1);
  const Settled s = settle(shaders(), p);
  const double lift = s.mean.obstacles[0].force.z, floor = -s.mean.walls[4].force.z;
  std::printf("box %.4f N (rho g V %.4f N); floor %.3f N of %.3f N\n", lift, kRho * 9.81 * 0.05 * 0.05 * 0.05, floor,
              s.weight);
  EXPECT_LT(lift, 0.0) << "pressed down";
  EXPECT_NEAR(floor - lift, s.weight, 0.002 * s.weight) << "the floor and the box carry every ball";
}
