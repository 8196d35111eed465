// Probes (water::Probes, shaders/water/gauge.comp): the gauge's sums against plain double loops
// over the particles read back (inside, beside a wall, in a corner; one window and many), the
// clipped footprint's kernel mass against geometry, the body probe against the obstacle's pose,
// and the gauge's accuracy: a resting tank reads its fill height (docs/WATER.md, "Probes").
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <numbers>
#include <random>

#include "gl/window.h"
#include "sim/balls/balls.h"
#include "sim/fluid/fluid.h"
#include "sim/fluid/sph_kernels.h"
#include "sim/water/obstacle_pose.h"
#include "sim/water/probes.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

using ProbesTest = test::GlTest;

// The gauge by plain loops in double: V Σ W(|xy − at|) / (the kernel's mass inside the walls).
double cpuGauge(const std::vector<glm::vec4>& pos, glm::dvec2 at, double R, double volume, double inside) {
  double sum = 0;
  for (const glm::vec4& p : pos) {
    const double s2 = (p.x - at.x) * (p.x - at.x) + (p.y - at.y) * (p.y - at.y);
    if (s2 < R * R) sum += 4.0 / (std::numbers::pi * R * R) * std::pow(1.0 - s2 / (R * R), 3.0);
  }
  return volume * sum / inside;
}

fluid::Params tank(float spacing, float fill) {
  fluid::Params p;
  p.setSpacing(spacing);
  p.domainMin = glm::vec3(0.0f);
  p.domainMax = glm::vec3(0.4f, 0.2f, 0.4f);
  p.fill = water::Fill::Slab;
  p.slabHeight = fill;
  p.dt = 0.002f;
  p.substeps = 8;
  return p;
}

}  // namespace

TEST(Probes, TheFootprintsKernelMassInsideTheWallsIsItsClippedShare) {
  const glm::vec2 lo(0.0f), hi(1.0f);
  EXPECT_EQ(water::gaugeKernelInside({0.5f, 0.5f}, 0.2, lo, hi), 1.0);
  EXPECT_NEAR(water::gaugeKernelInside({0.0f, 0.5f}, 0.2, lo, hi), 0.5, 1e-4) << "on a wall: half the disc";
  EXPECT_NEAR(water::gaugeKernelInside({0.0f, 0.0f}, 0.2, lo, hi), 0.25, 1e-4) << "in a corner: a quarter";
  // A wall at u = s/R = 0.5 cuts off the part beyond: by symmetry the kernel's mass with |x| > R/2,
  // computed here by plain quadrature in x of the kernel's line integrals.
  double beyond = 0;
  constexpr int n = 4000;
  for (int i = 0; i < n; ++i) {
    const double x = 0.5 + 0.5 * (i + 0.5) / n;  // in units of R
    double line = 0;
    for (int j = 0; j < n; ++j) {
      const double y = -1.0 + 2.0 * (j + 0.5) / n, s2 = x * x + y * y;
      if (s2 < 1) line += 4.0 / std::numbers::pi * std::pow(1 - s2, 3.0) * (2.0 / n);
    }
    beyond += line * 0.5 / n;
  }
  EXPECT_NEAR(water::gaugeKernelInside({0.9f, 0.5f}, 0.2, lo, hi), 1.0 - beyond, 1e-4);
}

TEST(Probes, ProbesOutsideWhatTheSceneHasAreNamed) {
  water::Setup s;
  s.domainMax = glm::vec3(1.0f, 0.5f, 1.0f);
  s.probes = {{.kind = water::ProbeKind::Gauge, .at = {0.5f, 0.6f, 0.0f}}};
  try {
    water::checkProbes(s);
    FAIL() << "a gauge outside the domain";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "probes[0]: the gauge at (0.5, 0.6) is not inside the domain's x (0, 1) and y (0, 0.5)");
  }
  s.probes = {{.kind = water::ProbeKind::Gauge, .at = {0.5f, 0.25f, 0.0f}},
              {.kind = water::ProbeKind::Body, .obstacle = 1}};
  s.obstacles.resize(1);
  try {
    water::checkProbes(s);
    FAIL() << "a body probe of an obstacle the scene does not have";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "probes[1]: obstacle 1 does not exist: the scene has 1 obstacle");
  }
  s.obstacles.resize(2);
  EXPECT_NO_THROW(water::checkProbes(s));
  EXPECT_EQ(water::probeColumns(s.probes).size(), 1u + 13u);
  EXPECT_EQ(water::probeColumns(s.probes)[0], "gauge0_height_m");
  EXPECT_EQ(water::probeColumns(s.probes)[1], "body1_x_m");
}

// Jittered water beside the walls; gauges inside, on a wall, in a corner and wider than the
// tank, with the array in one storage block and in windows of 4096 particles.
TEST_F(ProbesTest, GaugesEqualTheDoubleLoopsInOneWindowAndInMany) {
  fluid::Params p = tank(0.01f, 0.1f);  // 8,000 particles: two windows at the smallest block
  p.jitter = 0.3f;
  p.probes = {{.at = {0.2f, 0.1f, 0.0f}},
              {.at = {0.003f, 0.1f, 0.0f}, .radius = 0.04f},
              {.at = {0.39f, 0.19f, 0.0f}, .radius = 0.03f},
              {.at = {0.2f, 0.1f, 0.0f}, .radius = 0.5f}};
  fluid::Fluid fluid(shaders(), p);
  for (int i = 0; i < 3; ++i) fluid.stepOnce();
  const std::vector<glm::vec4> pos = fluid.positions().read<glm::vec4>(fluid.count());
  ASSERT_GT(pos.size(), gl::kWindowGrain);
  const double volume = water::volumePerParticle(fluid.radius(), fluid.packing());
  const glm::vec2 lo(fluid.wallMin()), hi(fluid.wallMax());
  std::vector<double> expected;
  for (const water::ProbeParams& g : p.probes) {
    const double R = water::gaugeRadius(g, fluid.radius());
    expected.push_back(
        cpuGauge(pos, glm::dvec2(g.at), R, volume, water::gaugeKernelInside(glm::vec2(g.at), R, lo, hi)));
  }
  water::Probes probes(shaders());
  for (std::size_t limit : {std::size_t(0), gl::kMinStorageBlockBytes}) {
    gl::overrideStorageBlockBytes(limit);
    const std::vector<double> got = probes.measure(fluid);
    gl::overrideStorageBlockBytes(0);
    ASSERT_EQ(got.size(), expected.size());
    for (std::size_t k = 0; k < got.size(); ++k)
      // fp32 sums within a work group of 128: 1e-6 of the height (measured: below 2e-7).
      EXPECT_NEAR(got[k], expected[k], 1e-6 * expected[k]) << "gauge " << k << ", block limit " << limit;
  }
}

TEST_F(ProbesTest, TheBodyProbeReadsTheObstaclesPoseAndVelocity) {
  fluid::Params p = tank(0.02f, 0.1f);
  water::ObstacleParams o;
  o.shape = water::Shape::Box;
  o.centre = {0.2f, 0.1f, 0.25f};
  o.size = {0.04f, 0.03f, 0.02f};
  o.orientation = {10.0f, 20.0f, 30.0f};
  o.spin = 0.7f;
  o.spinAxis = {0.0f, 0.0f, 1.0f};
  o.path = {water::PathKind::Oscillate, {0.05f, 0.0f, 0.0f}, 1.0f, 0.0f};
  p.obstacles = {o};
  p.probes = {{.kind = water::ProbeKind::Body, .obstacle = 0}};
  fluid::Fluid fluid(shaders(), p);
  for (int i = 0; i < 5; ++i) fluid.stepOnce();
  water::Probes probes(shaders());
  const std::vector<double> got = probes.measure(fluid);
  ASSERT_EQ(got.size(), 13u);
  const water::ObstaclePose pose = fluid.obstacles().pose(0);
  EXPECT_NE(pose, water::obstaclePose(o, 0.0)) << "it moved";
  glm::quat q = glm::quat_cast(pose.rotation);
  if (q.w < 0) q = -q;
  const double want[13] = {
      pose.centre.x,   pose.centre.y,   pose.centre.z,   q.w,          q.x,          q.y,         q.z,
      pose.velocity.x, pose.velocity.y, pose.velocity.z, pose.omega.x, pose.omega.y, pose.omega.z};
  for (int k = 0; k < 13; ++k) EXPECT_NEAR(got[std::size_t(k)], want[k], 1e-6) << water::probeColumns(p.probes)[k];
  EXPECT_NEAR(glm::length(glm::vec4(got[3], got[4], got[5], got[6])), 1.0, 1e-6) << "a unit quaternion";
  EXPECT_NEAR(got[12], 0.7, 1e-6) << "spin about z";
}

// The balls' fill is whole HCP layers (2r·√(2/3) apart) below the slab's height: at t = 0 the
// gauge reads those layers' height, the rule volumePerParticle(HCP) = (2r)³/√2 applied.
TEST_F(ProbesTest, AGaugeReadsTheBallsLatticesLayers) {
  balls::Params p;
  p.radius = 0.01f;
  p.domainMax = glm::vec3(0.4f, 0.2f, 0.4f);
  p.fill = water::Fill::Slab;
  p.slabHeight = 0.2f;
  p.probes = {{.at = {0.2f, 0.1f, 0.0f}}};
  balls::Balls balls(shaders(), p);
  const double layer = 2.0 * 0.01 * std::sqrt(2.0 / 3.0), layers = std::floor((0.2 - 2 * 0.01) / layer) + 1;
  water::Probes probes(shaders());
  EXPECT_NEAR(probes.measure(balls)[0], layers * layer, 0.01 * layers * layer);
}

// A tank of fluid filled 0.2 m deep, left to rest: gauges in the middle and off-centre read the
// fill height, each sample from t = 1 s to 2 s within 1.5% and their means within 1%; a gauge
// near a corner, its footprint cut by two walls, reads high, the fluid packing closer along the
// walls: its mean within 2% (docs/WATER.md, "Probes": measured 0.54% and 1.2%). The pressure
// 0.15 m and 0.1 m deep is ρ g d, the means within 3% (measured 0.24% and 1.6%).
TEST_F(ProbesTest, ARestingFluidTanksGaugesReadItsFillHeightAndItsPressureIsHydrostatic) {
  fluid::Params p = tank(0.02f, 0.2f);
  p.probes = {{.at = {0.2f, 0.1f, 0.0f}},
              {.at = {0.1f, 0.1f, 0.0f}},
              {.at = {0.32f, 0.08f, 0.0f}},
              {.at = {0.04f, 0.04f, 0.0f}}};
  const std::vector<glm::vec3> points = {{0.2f, 0.1f, 0.05f}, {0.2f, 0.1f, 0.1f}};
  const double depth[2] = {0.15, 0.1};
  double pressure[2] = {0, 0};
  fluid::Fluid fluid(shaders(), p);
  water::Probes probes(shaders());
  const std::vector<double> start = probes.measure(fluid);
  for (double h : start) EXPECT_NEAR(h, 0.2, 0.002) << "the cubic fill: 10 layers of 0.02 m";
  while (fluid.time() < 1.0) fluid.stepOnce();
  std::vector<double> mean(p.probes.size(), 0.0);
  int samples = 0;
  for (; fluid.time() < 2.0; ++samples) {
    const std::vector<double> h = probes.measure(fluid);
    for (std::size_t k = 0; k < h.size(); ++k) {
      EXPECT_NEAR(h[k], 0.2, 0.003) << "gauge " << k << " at t = " << fluid.time();
      mean[k] += h[k];
    }
    const std::vector<double> pa = fluid.pressures(points);
    for (int k = 0; k < 2; ++k) pressure[k] += pa[std::size_t(k)];
    for (int i = 0; i < 25; ++i) fluid.stepOnce();
  }
  for (int k = 0; k < 2; ++k) {
    const double rhoGd = 1000.0 * 9.81 * depth[k];
    std::printf("pressure %.2f m deep: mean %.1f Pa, rho g d = %.1f Pa\n", depth[k], pressure[k] / samples, rhoGd);
    EXPECT_NEAR(pressure[k] / samples, rhoGd, 0.03 * rhoGd) << depth[k] << " m deep";
  }
  for (std::size_t k = 0; k < mean.size(); ++k) {
    std::printf("gauge %zu: mean %.5f m over %d samples\n", k, mean[k] / samples, samples);
    EXPECT_NEAR(mean[k] / samples, 0.2, k == 3 ? 0.004 : 0.002) << "gauge " << k;
  }
}

// The pressure probe against plain double loops: Shepard's Σ V0 p_i W / Σ V0 W (poly6, h) over
// the particles read back with their Λ, p_i = −ρ0 Λ_i / dt²; and Λ is the sum of λ over the
// iterations: with one iteration it is that iteration's λ.
TEST_F(ProbesTest, PressuresEqualTheDoubleLoopsAndLambdaSumsTheIterations) {
  fluid::Params p = tank(0.02f, 0.2f);
  p.iterations = 1;
  fluid::Fluid one(shaders(), p);
  for (int i = 0; i < 20; ++i) one.stepOnce();
  const std::vector<float> sums = one.lambdaSums().read<float>(one.count());
  const std::vector<glm::vec2> lambdas = one.densities().read<glm::vec2>(one.count());
  for (std::size_t i = 0; i < sums.size(); ++i) ASSERT_EQ(sums[i], lambdas[i].x) << i;

  p.iterations = 4;
  fluid::Fluid fluid(shaders(), p);
  EXPECT_TRUE(std::isnan(fluid.pressures({{0.2f, 0.1f, 0.1f}})[0])) << "no step yet: no pressure";
  for (int i = 0; i < 50; ++i) fluid.stepOnce();
  const std::vector<glm::vec3> points = {{0.2f, 0.1f, 0.05f},  {0.03f, 0.1f, 0.1f},   {0.2f, 0.1f, 0.19f},
                                         {0.2f, 0.1f, 0.01f},  {0.39f, 0.19f, 0.02f}, {0.2f, 0.1f, 0.3f},
                                         {0.1f, 0.05f, 0.15f}, {0.3f, 0.15f, 0.1f},   {0.25f, 0.12f, 0.07f}};
  const std::vector<double> got = fluid.pressures(points);  // two batches of 8
  const std::vector<glm::vec4> pos = fluid.positions().read<glm::vec4>(fluid.count());
  const std::vector<float> lambda = fluid.lambdaSums().read<float>(fluid.count());
  const double h = fluid.h(), volume = fluid.rest().volume, scale = -1000.0 / (double(p.dt) * p.dt);
  ASSERT_EQ(got.size(), points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    double weighted = 0, weights = 0;
    for (std::size_t i = 0; i < pos.size(); ++i) {
      const glm::dvec3 r = glm::dvec3(points[k]) - glm::dvec3(glm::vec3(pos[i]));
      const double w = volume * fluid::poly6(glm::dot(r, r), h);
      weighted += w * scale * lambda[i];
      weights += w;
    }
    const double want = weights > 0 ? weighted / weights : 0.0;
    EXPECT_NEAR(got[k], want, 1e-5 * std::max(1.0, std::abs(want))) << "point " << k;
  }
  EXPECT_EQ(got[5], 0.0) << "above the water: no particle within h";
  EXPECT_GT(got[0], 1000.0) << "0.15 m deep";
}
