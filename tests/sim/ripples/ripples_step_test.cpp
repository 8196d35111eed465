// The GPU step equals the CPU reference; the seed rule keeps the seed's constants; total height
// is conserved with reflecting walls; auto substeps keep the Courant number under its target.
#include <gtest/gtest.h>

#include <random>

#include "base/log.h"
#include "reference/ripples_reference.h"
#include "sim/ripples/ripples.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::ripples;

namespace {

using RipplesTest = test::GlTest;

std::vector<float> randomState(int w, int h, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-0.05f, 0.05f);
  std::vector<float> hv(std::size_t(w) * h * 2);
  for (float& x : hv) x = u(rng);
  return hv;
}

Params small(Rule rule, Boundary boundary) {
  Params p;
  p.rule = rule;
  p.boundary = boundary;
  p.width = 40;  // not a multiple of the 16x16 tile
  p.height = 24;
  p.posDamping = 2.0f;
  p.spongeCells = 5;
  p.autoSubsteps = false;
  p.substeps = 1;
  return p;
}

}  // namespace

TEST_F(RipplesTest, GpuMatchesCpuReferenceForEveryRuleAndBoundary) {
  for (Rule rule : {Rule::Wave, Rule::Seed})
    for (Boundary boundary : {Boundary::Reflecting, Boundary::Absorbing, Boundary::Periodic}) {
      SCOPED_TRACE(std::string(kRuleNames[int(rule)]) + " / " + kBoundaryNames[int(boundary)]);
      const Params p = small(rule, boundary);
      Ripples gpu(shaders(), p);
      const std::vector<float> start = randomState(p.width, p.height, 7);
      gpu.upload(start);
      reference::State cpu = reference::fromInterleaved(p.width, p.height, start);
      const double dt = rule == Rule::Seed ? 0.005 : 0.004;  // C = 0.4 for the wave rule
      for (int i = 0; i < 5; ++i) {
        gpu.stepOnce(dt);
        reference::step(cpu, p, dt);
      }
      const std::vector<float> got = gpu.download();
      double scale = 0, worst = 0;
      for (std::size_t i = 0; i < cpu.h.size(); ++i) scale = std::max({scale, std::abs(cpu.h[i]), std::abs(cpu.v[i])});
      for (std::size_t i = 0; i < cpu.h.size(); ++i)
        worst = std::max({worst, std::abs(got[2 * i] - cpu.h[i]), std::abs(got[2 * i + 1] - cpu.v[i])});
      EXPECT_LT(worst / scale, 1e-6) << "worst relative difference after 5 steps";
    }
}

TEST(RipplesParams, SeedRuleDefaultsAreTheSeedsConstants) {
  const Params p;
  // water-simulation-gpu main.cpp: propagation c = 20, elasticity k = 0.7, friction f = 0.995,
  // dt = 10 x frame seconds, touch radius 0.03 of the grid.
  EXPECT_FLOAT_EQ(p.seedPropagation, 20.0f);
  EXPECT_FLOAT_EQ(p.seedElasticity, 0.7f);
  EXPECT_FLOAT_EQ(p.seedFriction, 0.995f);
  EXPECT_FLOAT_EQ(p.seedTimeScale, 10.0f);
  EXPECT_FLOAT_EQ(p.touchRadius, 0.03f);
}

TEST_F(RipplesTest, TotalHeightIsConservedWithReflectingWalls) {
  Params p = small(Rule::Wave, Boundary::Reflecting);
  p.velDamping = 0;
  p.posDamping = 0;
  p.width = 48;
  p.height = 40;
  Ripples r(shaders(), p);
  r.touch(0.3f, 0.6f, 0.2f, -0.5f);
  r.touch(0.7f, 0.3f, 0.1f, 0.8f);
  auto total = [&] {
    double sum = 0, magnitude = 0;
    const std::vector<float> hv = r.download();
    for (std::size_t i = 0; i < hv.size(); i += 2) {
      sum += hv[i];
      magnitude += std::abs(hv[i]);
    }
    return std::pair(sum, magnitude);
  };
  const auto [before, magnitude] = total();
  ASSERT_GT(std::abs(before), 1.0);
  const double dt = 0.5 * p.cellSize / p.waveSpeed;  // C = 0.5
  for (int i = 0; i < 1000; ++i) r.stepOnce(dt);
  const auto [after, magnitudeAfter] = total();
  EXPECT_NE(magnitudeAfter, magnitude) << "the surface must have moved";
  // fp32 round-off: each step adds dt*v to every height with a relative error ~6e-8.
  EXPECT_NEAR(after, before, 2e-5 * magnitude) << "sum of heights drifted";
}

TEST(RipplesParams, AutoSubstepsKeepTheCourantNumberUnderTheTarget) {
  Params p;
  p.waveSpeed = 2.0f;
  p.cellSize = 0.02f;
  p.courantTarget = 0.5f;
  for (double frame : {1.0 / 30, 1.0 / 60, 1.0 / 144, 0.001}) {
    p.frameSeconds = frame;
    const int n = substepsFor(p);
    EXPECT_LE(courant(p, frame / n), 0.5f * kCourantLimit2D + 1e-6f);
    if (n > 1) EXPECT_GT(courant(p, frame / (n - 1)), 0.5f * kCourantLimit2D) << "not the fewest substeps";
  }
  p.autoSubsteps = false;
  p.substeps = 3;
  EXPECT_EQ(substepsFor(p), 3);
}

TEST_F(RipplesTest, CourantAboveTheLimitIsWarnedInLogAndStatus) {
  Params p = small(Rule::Wave, Boundary::Reflecting);
  p.substeps = 1;
  p.frameSeconds = 0.8 * p.cellSize / p.waveSpeed;  // C = 0.8 > 0.707
  Ripples r(shaders(), p);
  std::vector<std::string> warnings;
  log::setSink([&](log::Level l, const std::string& m) {
    if (l == log::Level::Warn) warnings.push_back(m);
  });
  gl::GpuProfiler profiler;
  r.step(profiler);
  log::setSink(nullptr);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("exceeds the 2D stability limit"), std::string::npos);
  EXPECT_NE(r.status().find("UNSTABLE"), std::string::npos) << r.status();
}

TEST_F(RipplesTest, MovingSpherePushesWaterAsideWithoutCreatingIt) {
  Params p = small(Rule::Wave, Boundary::Reflecting);
  p.width = p.height = 64;
  p.velDamping = p.posDamping = 0;
  p.waveSpeed = 0;  // isolate the body coupling from wave propagation
  p.sphere = true;
  p.sphereRadius = 0.2f;  // 10 cells
  p.sphereHeight = 0.0f;
  p.sphereOrbit = 0.2f;
  p.spherePeriod = 1e6f;  // standing still
  Ripples still(shaders(), p);
  still.stepOnce(0.01);
  for (float x : still.download()) ASSERT_EQ(x, 0.0f) << "a resting sphere moves no water";

  p.spherePeriod = 4.0f;
  Ripples moving(shaders(), p);
  moving.stepOnce(0.05);
  const std::vector<float> hv = moving.download();
  double sum = 0, magnitude = 0, minH = 0, maxH = 0;
  for (std::size_t i = 0; i < hv.size(); i += 2) {
    sum += hv[i];
    magnitude += std::abs(hv[i]);
    minH = std::min(minH, double(hv[i]));
    maxH = std::max(maxH, double(hv[i]));
  }
  EXPECT_LT(minH, -1e-4) << "water ahead of the sphere is pushed down";
  EXPECT_GT(maxH, 1e-4) << "and flows back behind it";
  EXPECT_LT(std::abs(sum), 1e-3 * magnitude) << "the same submerged volume before and after: no water created";
}
