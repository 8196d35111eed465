// Dynamic obstacles in the fluid against theory (docs/ACCURACY.md, "Floating bodies"): a flat box
// dropped into a tank floats with ρ_b/ρ of its height under water, and one denser than water
// sinks and rests on the floor. The draft is the water level less the box's bottom, the level
// being the water's volume and the volume the box displaces (m / ρ) over the tank's floor.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/fluid/fluid.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

using FloatingBodiesTest = test::GlTest;

constexpr double kRho = 1000.0;
constexpr float kSpacing = 0.01f;
const glm::vec3 kTank(0.16f, 0.16f, 0.2f), kHalf(0.05f, 0.05f, 0.025f);

// A tank 0.16 × 0.16 m filled 0.06 m deep, and a box 0.1 × 0.1 × 0.05 m of `density` just above
// the water. Its width is four times its height, so it floats upright at each density here
// (a cube of 500 kg/m³ would turn onto an edge).
fluid::Params tankWithABox(float density) {
  fluid::Params p;
  p.setSpacing(kSpacing);
  p.domainMax = kTank;
  p.fill = water::Fill::Slab;
  p.slabHeight = 0.06f;
  p.dt = 0.002f;
  water::ObstacleParams box;
  box.shape = water::Shape::Box;
  box.size = kHalf;
  box.centre = glm::vec3(0.08f, 0.08f, 0.06f + kHalf.z + kSpacing);
  box.dynamic = true;
  box.density = density;
  p.obstacles = {box};
  return p;
}

struct Settled {
  glm::dvec3 centre{0.0};  // mean over the last half second, m
  double level = 0;        // the water level the water's and the displaced volume make, m
  double speed = 0;        // the largest of the last half second, m/s
};

// Two seconds: the box falls in, bobs, and settles; the last half second is averaged.
Settled settle(fluid::Fluid& fluid) {
  Settled out;
  int n = 0;
  while (fluid.time() < 2.0) {
    fluid.stepOnce();
    if (fluid.time() < 1.5) continue;
    out.centre += glm::dvec3(fluid.obstacles().pose(0).centre);
    out.speed = std::max(out.speed, glm::length(fluid.bodies().body(0).velocity()));
    ++n;
  }
  out.centre /= n;
  const double water = double(fluid.count()) * fluid.mass() / kRho;
  out.level = (water + fluid.bodies().body(0).mass().mass / kRho) / (double(kTank.x) * kTank.y);
  return out;
}

}  // namespace

// Boxes of 250, 500 and 750 kg/m³ float with a quarter, a half and three quarters of their height
// under water, within 3% of the height (measured +0.3%, −0.1% and +0.7% of it).
TEST_F(FloatingBodiesTest, FlatBoxesFloatWithTheirDensityOverWatersOfTheirHeightUnderWater) {
  const double height = 2.0 * kHalf.z;
  for (float density : {250.0f, 500.0f, 750.0f}) {
    fluid::Fluid fluid(shaders(), tankWithABox(density));
    ASSERT_TRUE(fluid.bodies().dynamic(0));
    const Settled s = settle(fluid);
    const double draft = s.level - (s.centre.z - kHalf.z), want = density / kRho * height;
    std::printf("%g kg/m^3: draft %.4f m, theory %.4f m (%+.1f%% of the height), fastest %.3g m/s\n", density, draft,
                want, 100 * (draft - want) / height, s.speed);
    EXPECT_NEAR(draft, want, 0.03 * height) << density << " kg/m^3";
    EXPECT_LT(s.speed, 0.02) << density << " kg/m^3: still bobbing";
    EXPECT_NEAR(s.centre.x, 0.08, 0.005) << "it drifted to a wall";
  }
}

// A box of 2000 kg/m³ sinks and rests on the floor, on the last layer of water particles under it
// (which the particles cannot squeeze out): its lowest particle less than a spacing above touching
// the floor, and still.
TEST_F(FloatingBodiesTest, ABoxDenserThanWaterSinksAndRestsOnTheFloor) {
  fluid::Fluid fluid(shaders(), tankWithABox(2000.0f));
  const Settled s = settle(fluid);
  const water::ObstacleBody& body = fluid.obstacles().body(0);
  double lowest = 1e30;
  for (const glm::vec4& q : body.particles) lowest = std::min(lowest, double(fluid.obstacles().pose(0).place(q).z));
  std::printf("lowest particle %.4f m, touching at %.4f m; fastest %.3g m/s\n", lowest, 0.5 * kSpacing, s.speed);
  EXPECT_GT(lowest, 0.5 * kSpacing - 1e-4) << "in the floor";
  EXPECT_LT(lowest, 1.5 * kSpacing) << "not on the floor";
  EXPECT_LT(s.speed, 0.005);
}
