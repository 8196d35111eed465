// The GPU fluid step equals the CPU reference (tests/reference/pbf_reference.h): one solver
// iteration alone, then several with XSPH, vorticity confinement and an obstacle's boundary
// particles, in both grid reorder modes; and the loads on the walls and the obstacle (force,
// torque) equal the reference's sums of the boundaries' shares, without changing the step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "reference/pbf_reference.h"
#include "sim/fluid/fluid.h"
#include "sim/water/water_init.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::fluid;

namespace {

using FluidTest = test::GlTest;

// The README's figure: fp32 against double, measured 2.2e-6 (one iteration) and 2.5e-6 (three,
// with XSPH, vorticity, damping and the shell) of the largest displacement and speed.
constexpr double kStepError = 4e-6;
// The loads' figure: float sums of the step's shares against double, measured 1.0e-6 (walls) and
// up to 3.4e-6 (the obstacles' forces and torques) of the largest load of their kind.
constexpr double kLoadError = 1e-5;

Params box() {
  Params p;
  p.setSpacing(0.02f);
  p.domainMin = glm::vec3(0.0f);
  p.domainMax = glm::vec3(0.2f, 0.2f, 0.3f);
  p.fill = water::Fill::None;
  p.dt = 1.0f / 600.0f;
  p.viscosity = 0.0f;
  return p;
}

// A squeezed, jittered cubic lattice (4% closer than at rest, 13% denser) moving at random: every
// particle's constraint is active, the walls and the s_corr term act.
void squeezed(std::vector<glm::vec4>& pos, std::vector<glm::vec4>& vel, const Params& p) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> jitter(-0.002f, 0.002f), speed(-0.3f, 0.3f);
  const float d = 0.96f * p.spacing();
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 7; ++i) {
        pos.emplace_back(glm::vec3(0.01f) + d * glm::vec3(i, j, k) + glm::vec3(jitter(rng), jitter(rng), jitter(rng)),
                         1.0f);
        vel.emplace_back(speed(rng), speed(rng), speed(rng), 0.0f);
      }
}

reference::Setup setupOf(const Fluid& f) {
  const Params& p = f.params();
  reference::Setup s;
  s.h = f.h();
  s.volume = f.rest().volume;
  s.epsilon = p.relaxation * f.rest().gradients;
  s.scorrK = p.scorrK / f.rest().gradients;
  s.scorrN = p.scorrN;
  s.scorrDq = p.scorrDq;
  s.dt = p.dt;
  s.decay = std::exp(-double(p.damping) * p.dt);
  s.viscosity = p.viscosity;
  s.vorticity = p.vorticity;
  s.contact = Fluid::kObstacleContact * p.spacing();
  s.inset = 0.5 * p.spacing();
  s.wallScale = f.rest().wallScale;
  s.iterations = p.iterations;
  s.gravity = glm::dvec3(p.gravity);
  s.wallMin = glm::dvec3(p.domainMin);
  s.wallMax = glm::dvec3(p.domainMax);
  return s;
}

// Largest difference of the displacement x_new − x_old (GPU, float) from the reference's, as a
// fraction of the largest reference displacement; the order maps GPU slots to the inputs.
double compare(const std::vector<glm::vec4>& before, const std::vector<glm::vec4>& after,
               const std::vector<GLuint>& order, const reference::State& cpu, const std::vector<glm::dvec3>& x0,
               double* velocityError, const std::vector<glm::vec4>& vel) {
  double worst = 0, largest = 0, vWorst = 0, vLargest = 0;
  for (std::size_t k = 0; k < after.size(); ++k) {
    const std::size_t i = order[k];
    const glm::dvec3 dRef = cpu.x[i] - x0[i];
    const glm::dvec3 dGpu = glm::dvec3(glm::vec3(after[k])) - glm::dvec3(glm::vec3(before[i]));
    worst = std::max(worst, glm::length(dGpu - dRef));
    largest = std::max(largest, glm::length(dRef));
    vWorst = std::max(vWorst, glm::length(glm::dvec3(glm::vec3(vel[k])) - cpu.v[i]));
    vLargest = std::max(vLargest, glm::length(cpu.v[i]));
  }
  *velocityError = vWorst / vLargest;
  return worst / largest;
}

struct StepRun {
  double displacement = 0, velocity = 0;  // relative errors (compare())
  std::vector<glm::vec4> positions;       // the GPU's, after the step
  water::Loads loads;                     // the GPU's, with a force probe listed
  reference::State cpu;
  double scale = 0;  // −m / dt²: the reference's sums to forces
};

// `obstacles`: 0; 1: a sphere's shell just above the block, within h of its top; 2: and a solid
// box in the block's corner, which pushes the particles inside it out to the contact distance;
// 3: and a small solid sphere beside the box, so that particles between them have both in reach.
// `again`: the GPU takes a step from the state first, and the compared step from the same state
// again (what one step left in the loads' partials must not reach the next).
StepRun run(gl::ShaderLibrary& shaders, Params p, int obstacles, bool again = false) {
  if (obstacles > 0) {
    water::ObstacleParams o;
    o.shape = water::Shape::Sphere;
    o.centre = glm::vec3(0.07f, 0.06f, 0.125f);
    o.size = glm::vec3(0.03f);
    o.shell = true;
    p.obstacles.push_back(o);
  }
  if (obstacles > 1) {
    water::ObstacleParams o;
    o.shape = water::Shape::Box;
    o.centre = glm::vec3(0.025f, 0.03f, 0.02f);
    o.size = glm::vec3(0.012f, 0.018f, 0.01f);
    o.orientation = glm::vec3(10.0f, 20.0f, 30.0f);
    p.obstacles.push_back(o);
  }
  if (obstacles > 2) {
    water::ObstacleParams o;
    o.centre = glm::vec3(0.055f, 0.03f, 0.02f);
    o.size = glm::vec3(0.008f);
    p.obstacles.push_back(o);
  }
  std::vector<glm::vec4> pos, vel;
  squeezed(pos, vel, p);
  Fluid gpu(shaders, p);
  gpu.upload(pos, vel);
  gpu.trackOrder(true);
  reference::State cpu;
  std::vector<glm::dvec3> x0;
  for (std::size_t i = 0; i < pos.size(); ++i) {
    cpu.x.emplace_back(glm::vec3(pos[i]));
    cpu.v.emplace_back(glm::vec3(vel[i]));
  }
  x0 = cpu.x;
  reference::Setup s = setupOf(gpu);
  const double solid = restLattice(p.spacing(), gpu.h(), water::Packing::Hcp).volume;  // as Fluid's solids
  for (std::size_t k = 0; k < p.obstacles.size(); ++k) {
    const water::ObstacleParams& o = p.obstacles[k];
    const water::ObstaclePose pose = gpu.obstacles().pose(k);
    s.centres.push_back(glm::dvec3(pose.centre));
    const std::vector<glm::vec4> body = water::Obstacle(o, 0.5f * p.spacing()).particles();
    const std::vector<float> volumes = boundaryVolumes(body, o.shell, gpu.h(), o.shell ? gpu.rest().volume : solid);
    for (std::size_t b = 0; b < body.size(); ++b)
      s.boundary.push_back({glm::dvec3(pose.centre) + glm::dmat3(pose.rotation) * glm::dvec3(glm::vec3(body[b])),
                            double(volumes[b]), int(k)});
  }
  if (again) {
    gpu.stepOnce();
    gpu.upload(pos, vel);
  }
  gpu.stepOnce();
  reference::step(s, cpu);
  StepRun out;
  out.positions = gpu.downloadPositions();
  out.displacement = compare(pos, out.positions, gpu.lastOrder(), cpu, x0, &out.velocity, gpu.downloadVelocities());
  if (!p.probes.empty()) out.loads = gpu.loads();
  out.cpu = cpu;
  out.scale = -gpu.mass() / (double(p.dt) * p.dt);
  return out;
}

}  // namespace

TEST_F(FluidTest, OneSolverIterationEqualsTheCpuReference) {
  Params p = box();
  p.iterations = 1;
  const StepRun r = run(shaders(), p, 0);
  std::printf("one iteration: displacement error %.3g, velocity error %.3g (relative)\n", r.displacement, r.velocity);
  EXPECT_LT(r.displacement, kStepError);
  EXPECT_LT(r.velocity, kStepError);
}

TEST_F(FluidTest, IterationsViscosityVorticityAndObstacleEqualTheCpuReference) {
  Params p = box();
  p.iterations = 3;
  p.viscosity = 0.05f;
  p.vorticity = 0.5f;
  p.damping = 3.0f;  // 1/s: strong enough that damping before gravity shows (2.6e-5)
  const StepRun r = run(shaders(), p, 1);
  std::printf("3 iterations, XSPH, vorticity, sphere shell: displacement error %.3g, velocity error %.3g\n",
              r.displacement, r.velocity);
  EXPECT_LT(r.displacement, kStepError);
  EXPECT_LT(r.velocity, kStepError);
}

// The step with three obstacles measuring the loads (force probes on an obstacle and a wall): the
// positions are bit for bit those of the step without; each wall's force and each obstacle's force and torque equal
// the reference's, within kLoadError of the largest load of their kind. With the obstacle's probe
// alone (predict then only clears the partials), a step taken twice from the same state reads the
// same obstacles' loads the second time.
TEST_F(FluidTest, LoadsOnTheWallsAndTheObstaclesEqualTheCpuReferenceAndLeaveTheStepAlone) {
  Params p = box();
  p.iterations = 3;
  const StepRun plain = run(shaders(), p, 3);
  p.probes = {{.kind = water::ProbeKind::Force, .obstacle = 0}};
  const StepRun obstaclesOnly = run(shaders(), p, 3, true);  // a second step: predict only clears
  EXPECT_TRUE(std::isnan(obstaclesOnly.loads.walls[0].force.x)) << "no probe on a wall: walls not measured";
  p.probes.push_back({.kind = water::ProbeKind::Force, .wall = water::ProbeWall::MaxZ});
  const StepRun r = run(shaders(), p, 3);
  ASSERT_EQ(r.positions.size(), plain.positions.size());
  for (std::size_t i = 0; i < r.positions.size(); ++i) ASSERT_EQ(r.positions[i], plain.positions[i]) << i;
  EXPECT_LT(r.displacement, kStepError) << "the step with a turned box pushing particles out";

  double wallLargest = 0, wallWorst = 0;
  for (std::size_t w = 0; w < water::kWalls; ++w) {
    const double want = r.scale * r.cpu.wall[w];
    glm::dvec3 along(0.0);
    along[int(w / 2)] = want;
    wallLargest = std::max(wallLargest, std::abs(want));
    wallWorst = std::max(wallWorst, glm::length(r.loads.walls[w].force - along));
    EXPECT_EQ(r.loads.walls[w].torque, glm::dvec3(0.0));
  }
  std::printf("walls: largest %.4g N, error %.3g\n", wallLargest, wallWorst / wallLargest);
  EXPECT_GT(wallLargest, 0.0);
  EXPECT_LT(wallWorst / wallLargest, kLoadError);  // fails on NaN too
  ASSERT_EQ(r.loads.obstacles.size(), 3u);
  ASSERT_EQ(obstaclesOnly.loads.obstacles.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const glm::dvec3 force = r.scale * r.cpu.obstacle[k], torque = r.scale * r.cpu.moment[k];
    const double forceError = glm::length(r.loads.obstacles[k].force - force) / glm::length(force);
    const double torqueError = glm::length(r.loads.obstacles[k].torque - torque) / glm::length(torque);
    std::printf("obstacle %zu: %.4g N, error %.3g; torque %.4g N m, error %.3g\n", k, glm::length(force), forceError,
                glm::length(torque), torqueError);
    EXPECT_GT(glm::length(force), 0.0) << "the block presses on obstacle " << k;
    EXPECT_LT(forceError, kLoadError) << k;
    EXPECT_LT(torqueError, kLoadError) << k;
    EXPECT_LT(glm::length(obstaclesOnly.loads.obstacles[k].force - force) / glm::length(force), kLoadError)
        << k << ", the second step without a wall probe";
  }
}
