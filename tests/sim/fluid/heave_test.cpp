// A floating box's heave against linear potential flow in the same tank
// (tests/reference/heave_reference.h), and that reference's free surface against Lamb's sloshing.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/constants.hpp>

#include "reference/heave_reference.h"
#include "sim/fluid/fluid.h"
#include "support/fluid_fixtures.h"
#include "support/gl_test.h"

using namespace tidepool;

// The reference's free surface alone: the tank's first mode symmetric about its middle, started
// as η = A cos(2πx/L), swings with ω² = g k tanh(k h), k = 2π/L (Lamb, "Hydrodynamics", 1932:
// standing waves in a rectangular tank).
TEST(HeaveReference, AnEmptyTanksSloshingHasLambsPeriod) {
  test::HeaveTank tank;
  tank.length = 0.3;
  tank.width = 0.08;
  tank.depth = 0.12;
  const test::HeaveReference ref(tank, 0.005);
  test::HeaveReference::State s = ref.rest();
  for (std::size_t f = 0; f < ref.surfaceFaces(); ++f)
    s.eta[f] = 1e-3 * std::cos(2 * glm::pi<double>() * ref.surfaceX(f) / tank.length);
  const double k = 2 * glm::pi<double>() / tank.length;
  const double period = 2 * glm::pi<double>() / std::sqrt(tank.g * k * std::tanh(k * tank.depth));
  std::vector<double> edge;
  const double dt = 1e-4;
  for (int i = 0; i < int(2.5 * period / dt); ++i) ref.advance(s, dt, 1), edge.push_back(s.eta[0]);
  const std::vector<double> turns = test::turningPoints(edge, dt, 1e-4);
  ASSERT_GE(turns.size(), 4u);
  const double measured = turns[3] - turns[1];
  std::printf("sloshing period %.5f s, Lamb %.5f s (%+.3f%%)\n", measured, period, 100 * (measured - period) / period);
  EXPECT_NEAR(measured, period, 0.002 * period);
}

namespace {

using HeaveTest = test::GlTest;

// A tank 0.3 × 0.12 m filled 0.12 m deep, and a box 0.12 × 0.08 × 0.05 m of 600 kg/m³ (draft
// 0.03 m) set on the water in its middle: wide enough to float upright both ways, 2 cm of
// freeboard, so that the water it moves stays off its top.
const glm::vec3 kTank(0.3f, 0.12f, 0.25f), kBoxHalf(0.06f, 0.04f, 0.025f);
constexpr float kDepth = 0.12f, kBoxDensity = 600.0f;
constexpr double kWatched = 0.7;  // s after the box is let go: a period and a half

fluid::Params tankWithAFloatingBox(float spacing) {
  const glm::vec3 centre(0.5f * kTank.x, 0.5f * kTank.y, kDepth + kBoxHalf.z + spacing);
  return test::tankWithABox(spacing, kTank, kDepth, centre, kBoxHalf, kBoxDensity);
}

}  // namespace

// The box is held down by an extra 30% of its weight until the water has settled around it, then
// let go: it swings up and back down. The time it takes to come back to its lowest point, one
// heave period, is the potential-flow reference's within 10% (measured +1.9% on llvmpipe, +4.9%
// on the H200; docs/WATER.md, "Floating bodies", has the other spacings). The reference starts from
// the same state: the box pushed down, the water level raised evenly by what it displaces.
TEST_F(HeaveTest, AFloatingBoxLetGoComesBackAfterThePeriodOfPotentialFlow) {
  const float spacing = 0.01f;
  fluid::Fluid fluid(shaders(), tankWithAFloatingBox(spacing));
  const double mass = fluid.bodies().body(0).mass().mass, dt = fluid.params().dt;
  const double push = 0.3 * mass * 9.81;
  while (fluid.time() < 1.5) {  // the push: its impulse added each step
    std::vector<water::BodyState> states = fluid.bodies().states();
    states[0].momentum.z -= push * dt;
    fluid.bodies().setStates(states);
    fluid.stepOnce();
  }
  std::vector<double> heave;
  const double released = fluid.time();
  while (fluid.time() < released + kWatched) {
    heave.push_back(fluid.bodies().body(0).state().position.z);
    fluid.stepOnce();
  }
  const std::vector<double> turns = test::turningPoints(heave, dt, 0.05 * spacing);

  test::HeaveTank tank;
  tank.length = kTank.x, tank.width = kTank.y, tank.depth = kDepth;
  tank.boxLength = 2 * kBoxHalf.x, tank.boxWidth = 2 * kBoxHalf.y;
  tank.draft = kBoxDensity / tank.rho * 2 * kBoxHalf.z;
  tank.mass = mass;
  const test::HeaveReference ref(tank, 0.005);
  test::HeaveReference::State s = ref.pushed(-0.004);
  std::vector<double> theory;
  const double sample = 5e-4;  // the reference's trace, each sample five steps of 0.1 ms
  for (long i = 0; i < std::lround(kWatched / sample); ++i) theory.push_back(s.z), ref.advance(s, sample / 5, 5);
  const std::vector<double> theoryTurns = test::turningPoints(theory, sample, 1e-5);
  ASSERT_GE(theoryTurns.size(), 3u);
  ASSERT_GE(turns.size(), 3u) << "it did not come back down";
  std::printf(
      "box %.3f kg, added mass at infinite frequency %.3f kg; highest at %.3f s (theory %.3f), lowest again "
      "at %.3f s (theory %.3f, %+.1f%%)\n",
      mass, ref.addedMass(), turns[1], theoryTurns[1], turns[2], theoryTurns[2],
      100 * (turns[2] - theoryTurns[2]) / theoryTurns[2]);
  EXPECT_NEAR(turns[2], theoryTurns[2], 0.1 * theoryTurns[2]);
}
