// Dynamic obstacles on the balls (sim/water/body_coupling.h): a box dropped onto the balls comes to
// rest carried by their contacts, and how far it sinks in is what the cheap water model gets
// against the fluid's theory (docs/WATER.md, "Floating bodies").
#include <gtest/gtest.h>

#include <cmath>

#include "sim/balls/balls.h"
#include "support/body_fixtures.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::balls;

namespace {

using BallsBodies = test::GlTest;

constexpr double kRho = 1000.0;
const glm::vec3 kTank(0.16f, 0.16f, 0.2f), kHalf(0.04f, 0.04f, 0.02f);
constexpr float kDepth = 0.05f;

// Balls of r = 5 mm filling a tank 0.16 × 0.16 m 0.05 m deep, and a box 0.08 × 0.08 × 0.04 m of
// `density` just above them.
Params tankWithABox(float density) {
  Params p;
  p.radius = 0.005f;
  p.domainMax = kTank;
  p.fill = water::Fill::Slab;
  p.slabHeight = kDepth;
  p.dt = 4e-4f;
  p.contactTime = 0.008f;
  p.obstacles = {test::dynamicBox(kHalf, glm::vec3(0.08f, 0.08f, kDepth + kHalf.z + 0.01f), density)};
  return p;
}

struct Settled {
  glm::dvec3 centre{0.0};  // mean over the last half second, m
  glm::dvec3 load{0.0};    // the balls' mean force on the box then, N
  double level = 0;        // the water level the balls' rest volume and the displaced volume make, m
};

// A second and a half: the box falls in and settles; the last half second is averaged.
Settled settle(Balls& balls) {
  Settled out;
  int n = 0;
  while (balls.time() < 1.5) {
    balls.stepOnce();
    if (balls.time() < 1.0) continue;
    out.centre += glm::dvec3(balls.obstacles().pose(0).centre);
    out.load += balls.bodies().body(0).state().force;
    ++n;
  }
  out.centre /= n;
  out.load /= n;
  const double water = double(balls.count()) * water::volumePerParticle(balls.radius(), Params::kPacking);
  out.level = (water + balls.bodies().body(0).mass().mass / kRho) / (double(kTank.x) * kTank.y);
  return out;
}

}  // namespace

// A box of 500 kg/m³ dropped onto the balls comes to rest on them, carried by their contacts: the
// mean force they put on it is its weight within 1% (measured +0.01%: the coupling's momentum
// balance). It floats high, 4% of its height under the level where water would hold half: a pile
// of balls at rest is a granular solid that carries a box as sand would (docs/WATER.md,
// "Floating bodies").
TEST_F(BallsBodies, ABoxDroppedOnTheBallsComesToRestCarriedByTheirContacts) {
  Balls balls(shaders(), tankWithABox(500.0f));
  const Settled s = settle(balls);
  const double weight = balls.bodies().body(0).mass().mass * 9.81;
  const double bottom = s.centre.z - kHalf.z, draft = (s.level - bottom) / (2 * kHalf.z);
  std::printf("load %.4f N, weight %.4f N (%+.2f%%); draft %.3f of the height (water: 0.5)\n", s.load.z, weight,
              100 * (s.load.z / weight - 1), draft);
  EXPECT_NEAR(s.load.z, weight, 0.01 * weight);
  EXPECT_NEAR(s.load.x, 0.0, 0.01 * weight);
  EXPECT_NEAR(s.load.y, 0.0, 0.01 * weight);
  EXPECT_GT(draft, 0.0) << "in the balls, not on them";
  EXPECT_LT(draft, 0.5) << "higher than in water";
}
