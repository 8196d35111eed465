// The fluid behaves like water, to the figures the README gives: a resting tank keeps its density
// error near 0.071% with four iterations (0.027% with eight), its surface and every particle; the
// dam break runs 2 s stable with every particle kept and a front that only advances, and follows
// Martin & Moyce's measured front to the RMS docs/WATER.md gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "scene/fluid_stage.h"
#include "sim/fluid/fluid.h"
#include "support/gl_test.h"
#include "sweep/water_run.h"

using namespace tidepool;
using namespace tidepool::fluid;

namespace {

using FluidTest = test::GlTest;

Params sceneParams(const char* name) { return fluidScene(loadScene(resolveScenePath(name))).model; }

void run(Fluid& f, double seconds) {
  while (f.time() < seconds - 1e-9) f.stepOnce();
}

// The free surface of water at rest: the height of the level column with the same centre of mass,
// 2·mean(z − floor) (robust to the few particles a liquid surface lifts above the rest).
double surface(Fluid& f) {
  double sum = 0;
  const std::vector<glm::vec4> pos = f.downloadPositions();
  for (const glm::vec4& p : pos) sum += p.z - f.wallMin().z;
  return 2.0 * sum / double(pos.size());
}

// Every particle at least half a spacing inside each wall (the collision's inset), none NaN.
void expectInsideTheWalls(Fluid& f) {
  const glm::vec3 lo = f.wallMin() + 0.5f * f.params().spacing() - 1e-5f;
  const glm::vec3 hi = f.wallMax() - 0.5f * f.params().spacing() + 1e-5f;
  std::size_t outside = 0;
  for (const glm::vec4& p : f.downloadPositions())
    if (!(glm::all(glm::greaterThanEqual(glm::vec3(p), lo)) && glm::all(glm::lessThanEqual(glm::vec3(p), hi))))
      ++outside;
  EXPECT_EQ(outside, 0u);
}

}  // namespace

TEST_F(FluidTest, RestingTankDensityErrorIsTheDocumentedFigureAndFallsWithIterations) {
  std::vector<double> errors;
  for (int iterations : {1, 2, 4, 8}) {
    Params p = sceneParams("fluid-tank");
    p.iterations = iterations;
    Fluid f(shaders(), p);
    run(f, 0.4);
    double sum = 0;  // the mean over 0.1 s of samples
    for (int k = 0; k < 5; ++k) {
      run(f, 0.4 + 0.02 * (k + 1));
      sum += f.stats().compressionMean;
    }
    errors.push_back(sum / 5);
    std::printf("resting tank, %d iterations: mean density error %.3g%%\n", iterations, 100 * errors.back());
  }
  // The README's 0.071% (4 iterations) and 0.027% (8), each with a margin of about 12%.
  EXPECT_LT(errors[2], 0.0008);
  EXPECT_LT(errors[3], 0.0003);
  for (std::size_t k = 1; k < errors.size(); ++k) EXPECT_LE(errors[k], errors[k - 1] * 1.05) << k;
  EXPECT_LT(errors.back(), 0.5 * errors.front());
}

TEST_F(FluidTest, RestingTankKeepsItsSurfaceAndEveryParticleForTwoSeconds) {
  const Params p = sceneParams("fluid-tank");
  Fluid f(shaders(), p);
  const std::size_t count = f.count();
  const double filled = p.slabHeight;  // the cubic fill tiles the slab: its surface is the fill height
  EXPECT_NEAR(surface(f), filled, 1e-3 * filled);
  for (int k = 1; k <= 8; ++k) {
    run(f, 0.25 * k);
    const double s = surface(f);
    const Stats st = f.stats();
    std::printf("t = %.2f s: surface %.4f m (fill %.4f m), density error %.3g%%\n", f.time(), s, filled,
                100 * st.compressionMean);
    EXPECT_NEAR(s, filled, 0.005 * filled) << "t = " << f.time();  // the README's 0.5% (it settles 0.45% low)
    EXPECT_EQ(st.count, count);
    EXPECT_EQ(st.nonFinite, 0u);
    EXPECT_EQ(st.outside, 0u);
  }
  expectInsideTheWalls(f);
  EXPECT_FALSE(f.divergence().has_value());
}

TEST_F(FluidTest, DamBreakRunsTwoSecondsStableWithEveryParticleAndAnAdvancingFront) {
  const Params p = sceneParams("dam-break-fluid");
  Fluid f(shaders(), p);
  const std::size_t count = f.count();
  const double wall = p.domainMax.x - 0.5 * p.spacing();
  double front = 0;
  for (int k = 1; k <= 40; ++k) {
    run(f, 0.05 * k);
    const Stats st = f.stats();
    ASSERT_EQ(st.nonFinite, 0u) << "t = " << st.time;
    EXPECT_EQ(st.count, count);
    EXPECT_EQ(st.outside, 0u);
    if (front < wall - 1e-4) EXPECT_GE(st.front, front - 1e-4) << "t = " << st.time;  // until it reaches the far wall
    front = std::max(front, st.front);
  }
  EXPECT_GE(front, wall - 1e-3);  // the surge reached the far wall
  expectInsideTheWalls(f);
}

// The scene's front (d = 0.02 m, dt = 1 ms, 4 iterations) against Martin & Moyce's measured
// front over their four points to t = 0.3 s, sampled and compared as the water-front study does:
// docs/WATER.md gives RMS 0.22 a at this spacing; held to it within 0.03 a (about 12%) both
// ways, since a front that slows (more viscosity) first comes closer to theirs.
TEST_F(FluidTest, DamBreakFrontFollowsMartinAndMoyce) {
  const Params p = sceneParams("dam-break-fluid");
  sweep::WaterRun run(shaders(), p);
  constexpr double every = 0.004;  // s, as the study
  std::vector<double> front;
  for (int j = 1; j * every <= 0.3 + 1e-9; ++j) {
    run.advanceTo(j * every);
    const sweep::WaterSample s = run.sample(false);
    ASSERT_TRUE(s.healthy) << "t = " << s.time;
    front.push_back(s.front);
  }
  int points = 0;
  const double rms = sweep::rmsFromMartinMoyce(front, every, run.columnWidth(), -double(p.gravity.z), points);
  std::printf("dam break front at 0.3 s: %.3f a; RMS from Martin & Moyce %.3f a over %d points\n", front.back(), rms,
              points);
  EXPECT_EQ(points, 4);
  EXPECT_NEAR(rms, 0.22, 0.03);
}

// Boundary particles hold the water: the fluid-cup scene (coarser) pours a block into the cup; no
// particle ends inside the cup's walls or leaves the domain. Inside means the particle's sphere
// (radius d/2) lies in the solid: the analytic shape reaches half a lattice step beyond its outer
// particles, where water touching the wall legitimately sits.
TEST_F(FluidTest, NoParticleEntersAnObstacle) {
  Params p = sceneParams("fluid-cup");
  p.setSpacing(0.03f);
  Fluid f(shaders(), p);
  const std::size_t count = f.count();
  std::size_t inside = 0, worst = 0;
  for (int k = 1; k <= 6; ++k) {
    run(f, 0.1 * k);
    inside = 0;
    const float r = 0.5f * p.spacing();
    for (const glm::vec4& q : f.downloadPositions()) {
      bool deep = f.obstacles().occupied(glm::vec3(q));
      for (int axis = 0; axis < 3 && deep; ++axis)
        for (float s : {-r, r}) {
          glm::vec3 e(0.0f);
          e[axis] = s;
          deep = deep && f.obstacles().occupied(glm::vec3(q) + e);
        }
      inside += deep ? 1 : 0;
    }
    worst = std::max(worst, inside);
    EXPECT_EQ(f.stats().count, count);
  }
  std::printf("fluid cup: %zu particles, at most %zu inside the cup's walls\n", count, worst);
  EXPECT_EQ(worst, 0u);
  expectInsideTheWalls(f);
}

// The tap emits at the fluid's rest density: a jet falling from the nozzle is nowhere compressed
// (layers at the balls' packing would start it 60% over ρ0 and burst it into spray).
TEST_F(FluidTest, TapJetLeavesTheNozzleUncompressed) {
  Params p;
  p.setSpacing(0.02f);
  p.domainMax = glm::vec3(0.4f, 0.4f, 0.6f);
  p.fill = water::Fill::None;
  p.dt = 0.001f;
  p.tap = true;
  p.tapPosition = glm::vec3(0.2f, 0.2f, 0.5f);
  p.tapDirection = glm::vec3(0.0f, 0.0f, -1.0f);
  p.tapSpeed = 1.5f;
  p.tapRadius = 0.05f;
  Fluid f(shaders(), p);
  double worst = -1;
  for (int k = 1; k <= 10; ++k) {
    run(f, 0.02 * k);
    worst = std::max(worst, f.stats().compressionMax);
  }
  std::printf("tap jet: %zu particles, largest compression %.3g\n", f.count(), worst);
  EXPECT_GT(f.count(), 200u);
  EXPECT_LT(worst, 0.02);
}

// A particle with few neighbours, its density well under the rest density, is spray: its foam is
// raised to 1 − smoothstep(0.6 s, s, ρ/ρ0) (s = spray_density) and decays from there. One step of
// the dam break's splash against that rule, particle by particle (the foam's growth with speed
// off, so the rule is all there is).
TEST_F(FluidTest, ParticlesWellUnderTheRestDensityTurnToFoamAsSpray) {
  Params p = sceneParams("dam-break-fluid");
  p.foamGain = 0.0f;
  p.foamDecay = 0.999f;
  Fluid f(shaders(), p);
  f.trackOrder(true);
  run(f, 0.45);  // the surge has run up the far wall
  const std::vector<glm::vec4> before = f.downloadVelocities();
  f.stepOnce();
  const std::vector<glm::vec4> after = f.downloadVelocities();
  const std::vector<GLuint> order = f.lastOrder();
  const std::vector<glm::vec2> density = f.densities().read<glm::vec2>(f.count());
  const double s = p.sprayDensity, decay = std::pow(double(p.foamDecay), double(p.dt) / 0.0005);
  int spray = 0, partly = 0, water = 0;
  for (std::size_t k = 0; k < after.size(); ++k) {
    const double t = std::clamp((density[k].y - 0.6 * s) / (0.4 * s), 0.0, 1.0);
    const double airborne = 1.0 - t * t * (3.0 - 2.0 * t);
    const double want = std::min(1.0, std::max(double(before[order[k]].w), airborne) * decay);
    ASSERT_NEAR(after[k].w, want, 1e-5) << "particle " << k << ", density " << density[k].y;
    spray += airborne > 0.3, partly += airborne > 0.0 && airborne <= 0.3, water += airborne == 0.0;
  }
  std::printf("spray %d, partly %d, water %d\n", spray, partly, water);
  EXPECT_GT(spray, 0);
  EXPECT_GT(partly, 0);
  EXPECT_GT(water, int(0.9 * double(after.size())));
}
