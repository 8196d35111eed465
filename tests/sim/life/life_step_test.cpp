// The binned GPU forces equal the O(N^2) CPU brute force (walls and looping borders, particles
// on the seams); friction alone decays speed as exp(-friction·t) for both integrators.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "reference/life_reference.h"
#include "sim/life/life.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::life;

namespace {

using LifeTest = test::GlTest;

void expectForcesMatch(Life& model, const Rules& rules) {
  model.computeForces();
  const std::vector<glm::vec4> pos = model.positions().read<glm::vec4>(model.count());
  const std::vector<glm::vec2> got = model.accelerations().read<glm::vec2>(model.count());
  const std::vector<reference::ForceSum> want = reference::bruteForce(rules, pos);
  double worst = 0;
  int interacting = 0;
  for (std::size_t i = 0; i < pos.size(); ++i) {
    const double err = glm::length(glm::dvec2(got[i]) - want[i].force);
    worst = std::max(worst, err / (want[i].scale + 1e-3));
    interacting += want[i].scale > 0;
  }
  EXPECT_LT(worst, 1e-5) << "worst error relative to the sum of |contributions|";
  EXPECT_GT(interacting, int(pos.size()) * 9 / 10);
}

}  // namespace

TEST_F(LifeTest, BinnedForcesMatchBruteForce) {
  for (bool looping : {false, true}) {
    SCOPED_TRACE(looping ? "looping" : "walls");
    // 4096 particles at the article's density (65536 in 1024x576) in a box that is no multiple
    // of the cell (the largest radius), so the last cell of each axis is partial.
    Rules rules = generateRules({.species = 6,
                                 .particleCount = 4096,
                                 .size = {250.0f, 151.0f},
                                 .centralForce = 0.5f,
                                 .loopingBorders = looping,
                                 .seed = 21});
    Life model(shaders(), rules);
    // A tenth of the particles right on the seams, where wrapping and clamping matter.
    std::vector<glm::vec4> pos = model.positions().read<glm::vec4>(model.count());
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> edge(0.0f, 3.0f);
    for (std::size_t i = 0; i < pos.size(); i += 10) {
      const glm::vec2 half = 0.5f * rules.size;
      if (i % 20 == 0)
        pos[i].x = (i % 40 == 0 ? -half.x + edge(rng) : half.x - edge(rng));
      else
        pos[i].y = (i % 30 == 0 ? -half.y + edge(rng) : half.y - edge(rng));
    }
    model.upload(pos, model.velocities().read<glm::vec4>(model.count()));
    expectForcesMatch(model, rules);
    // And after a few steps of the real dynamics.
    for (int k = 0; k < 3; ++k) model.stepOnce(0.01f);
    expectForcesMatch(model, rules);
  }
}

TEST_F(LifeTest, FrictionAloneDecaysSpeedExponentially) {
  for (Integrator integrator : {Integrator::Euler, Integrator::Verlet}) {
    SCOPED_TRACE(kIntegratorNames[int(integrator)]);
    Rules rules = generateRules({.species = 2, .particleCount = 1024, .friction = 7.0f, .seed = 8});
    for (Species& s : rules.species)
      for (Force& f : s.forces) f = {0, 0, 10, 2};
    Params params;
    params.integrator = integrator;
    Life model(shaders(), rules, params);
    const auto speeds = [&] {
      std::vector<double> out;
      for (const glm::vec4& v : model.velocities().read<glm::vec4>(model.count()))
        out.push_back(glm::length(glm::vec2(v)));
      std::sort(out.begin(), out.end());  // particles are reordered: compare the sorted speeds
      return out;
    };
    const std::vector<double> before = speeds();
    const float dt = 0.01f;
    for (int i = 0; i < 20; ++i) model.stepOnce(dt);
    const std::vector<double> after = speeds();
    const double factor = std::exp(-7.0 * 20 * double(dt));
    for (std::size_t i = 0; i < before.size(); ++i) ASSERT_NEAR(after[i], before[i] * factor, 1e-5 * before[i] + 1e-7);
  }
}

TEST_F(LifeTest, PushBrushAddsAGaussianVelocityForOneStep) {
  Rules rules = generateRules({.species = 1, .particleCount = 1024, .friction = 0.0f, .seed = 2});
  rules.species[0].forces[0] = {0, 0, 4, 0};
  Life model(shaders(), rules);
  std::vector<glm::vec4> pos = model.positions().read<glm::vec4>(model.count());
  model.upload(pos, std::vector<glm::vec4>(model.count(), glm::vec4(0.0f)));
  const glm::vec2 centre(10.0f, -20.0f), push(30.0f, 0.0f);
  const float radius = 64.0f;
  model.push(centre, push, radius);
  model.stepOnce(0.01f);
  const std::vector<glm::vec4> p = model.positions().read<glm::vec4>(model.count());
  const std::vector<glm::vec4> v = model.velocities().read<glm::vec4>(model.count());
  for (std::size_t i = 0; i < p.size(); ++i) {
    // p moved by v·dt from where the brush saw it: evaluate the Gaussian there.
    const glm::vec2 before = glm::vec2(p[i]) - glm::vec2(v[i]) * 0.01f;
    const glm::vec2 r = before - centre;
    const float want = push.x * std::exp(-glm::dot(r, r) / (radius * radius));
    ASSERT_NEAR(v[i].x, want, 1e-3f * push.x);
    ASSERT_EQ(v[i].y, 0.0f);
  }
  model.stepOnce(0.01f);  // the brush acts once per push()
  const std::vector<glm::vec4> v2 = model.velocities().read<glm::vec4>(model.count());
  float maxSpeedBefore = 0, maxSpeedAfter = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    maxSpeedBefore = std::max(maxSpeedBefore, std::abs(v[i].x));
    maxSpeedAfter = std::max(maxSpeedAfter, std::abs(v2[i].x));
  }
  EXPECT_FLOAT_EQ(maxSpeedAfter, maxSpeedBefore);
}

TEST_F(LifeTest, VerletIsSecondOrderAndEulerFirstOnTheCentralForce) {
  // One particle, no pair forces, no friction: the central force -c·p is a harmonic oscillator,
  // p(t) = p0 cos(wt) + v0/w sin(wt) with w = sqrt(c). Halving dt divides the error at t = 1 by
  // about 2 for symplectic Euler and about 4 for velocity Verlet.
  Rules rules = generateRules(
      {.species = 1, .particleCount = 1, .size = {100, 100}, .friction = 0.0f, .centralForce = 4.0f, .seed = 1});
  rules.species[0].forces[0] = {0, 0, 10, 0};  // no force, but 10 x 10 cells
  const double w = 2.0, p0 = 30.0, v0 = 10.0;  // amplitude 30.4: never reaches the walls
  const double exact = p0 * std::cos(w) + v0 / w * std::sin(w);
  for (Integrator integrator : {Integrator::Euler, Integrator::Verlet}) {
    SCOPED_TRACE(kIntegratorNames[int(integrator)]);
    double errors[2];
    for (int k = 0; k < 2; ++k) {
      Params params;
      params.integrator = integrator;
      Life model(shaders(), rules, params);
      model.upload({glm::vec4(float(p0), 0.0f, 0.0f, 0.0f)}, {glm::vec4(float(v0), 0.0f, 0.0f, 0.0f)});
      const int steps = 50 << k;
      for (int i = 0; i < steps; ++i) model.stepOnce(1.0f / float(steps));
      errors[k] = std::abs(model.positions().read<glm::vec4>(1)[0].x - exact);
    }
    const double order = std::log2(errors[0] / errors[1]);
    EXPECT_NEAR(order, integrator == Integrator::Verlet ? 2.0 : 1.0, 0.2) << errors[0] << " " << errors[1];
  }
}
