// Dynamic obstacles in the fluid against theory (docs/WATER.md, "Floating bodies"): a flat box
// dropped into a tank floats with ρ_b/ρ of its height under water, and one denser than water
// sinks and rests on the floor. The draft is the water level less the box's bottom, the level
// being the water's volume and the volume the box displaces (m / ρ) over the tank's floor.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/fluid/fluid.h"
#include "support/fluid_fixtures.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

using FloatingBodiesTest = test::GlTest;

constexpr double kRho = 1000.0;
constexpr float kSpacing = 0.01f;
const glm::vec3 kTank(0.16f, 0.16f, 0.2f), kHalf(0.05f, 0.05f, 0.025f);

// tankWith: test::tankWithABox at kSpacing. tankWithABox: a tank 0.16 × 0.16 m filled 0.06 m
// deep, and a box 0.1 × 0.1 × 0.05 m of `density` just above the water. Its width is four times its height, so it
// floats upright at each density here (a cube of 500 kg/m³ would turn onto an edge).
fluid::Params tankWith(glm::vec3 tank, float depth, glm::vec3 centre, glm::vec3 half, float density) {
  return test::tankWithABox(kSpacing, tank, depth, centre, half, density);
}
fluid::Params tankWithABox(float density) {
  return tankWith(kTank, 0.06f, glm::vec3(0.08f, 0.08f, 0.06f + kHalf.z + kSpacing), kHalf, density);
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

namespace {

// A plank's cross-section (length along x, thickness along z) turned down θ about its hinge at
// the middle of its left end: the part under the level z = h, as a polygon clipped from the
// rectangle, its area and centroid.
struct Wet {
  double area = 0;
  glm::dvec2 centroid{0.0};
};
Wet under(const std::vector<glm::dvec2>& shape, double h) {
  std::vector<glm::dvec2> poly;
  for (std::size_t i = 0; i < shape.size(); ++i) {
    const glm::dvec2 a = shape[i], b = shape[(i + 1) % shape.size()];
    if (a.y <= h) poly.push_back(a);
    if ((a.y <= h) != (b.y <= h)) poly.push_back(a + (b - a) * ((h - a.y) / (b.y - a.y)));
  }
  Wet w;
  glm::dvec2 moment(0.0);
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec2 a = poly[i], b = poly[(i + 1) % poly.size()];
    const double cross = a.x * b.y - b.x * a.y;
    w.area += 0.5 * cross;
    moment += (a + b) * cross / 6.0;
  }
  if (w.area > 0.0) w.centroid = moment / w.area;
  return w;
}

// The angle θ (degrees below level) at which the buoyancy's moment about the hinge equals the
// weight's, the water level rising with the wet part: ρ A_wet (x_wet − x_p) = ρ_b L t (x_mid − x_p).
double flapAngle(glm::dvec2 pivot, double length, double thick, double width, double density, double water,
                 double floor) {
  auto turning = [&](double theta) {  // the moment turning it up, per ρ g
    const double c = std::cos(theta), s = std::sin(theta);
    auto at = [&](double along, double across) {
      return pivot + glm::dvec2(along * c + across * s, -along * s + across * c);
    };
    const std::vector<glm::dvec2> shape = {at(0, -thick / 2), at(length, -thick / 2), at(length, thick / 2),
                                           at(0, thick / 2)};
    double level = water / floor;
    Wet wet;
    for (int i = 0; i < 50; ++i) {
      wet = under(shape, level);
      level = (water + wet.area * width) / floor;
    }
    return wet.area * (wet.centroid.x - pivot.x) - density / kRho * length * thick * (at(length / 2, 0).x - pivot.x);
  };
  double lo = 0, hi = glm::half_pi<double>();
  for (int i = 0; i < 60; ++i) (turning(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
  return glm::degrees(lo);
}

}  // namespace

// A plank of 500 kg/m³ hinged at one end above the water swings down into it and settles where
// the buoyancy's moment about the hinge balances the weight's (the wet part of its cross-section
// found exactly, with the water level it raises): within 1° of that angle.
TEST_F(FloatingBodiesTest, APlankHingedAboveTheWaterSettlesWhereTheMomentsBalance) {
  const glm::vec3 tank(0.4f, 0.1f, 0.25f), half(0.12f, 0.04f, 0.015f);
  const glm::vec3 pivot(0.04f, 0.05f, 0.16f);
  fluid::Params p = tankWith(tank, 0.1f, pivot + glm::vec3(half.x, 0.0f, 0.0f), half, 500.0f);
  water::ObstacleParams& plank = p.obstacles[0];
  plank.hingeAxis = {0.0f, 1.0f, 0.0f};
  plank.hingeAt = {-half.x, 0.0f, 0.0f};
  fluid::Fluid fluid(shaders(), p);
  double angle = 0, fastest = 0;
  int n = 0;
  while (fluid.time() < 3.0) {
    fluid.stepOnce();
    if (fluid.time() < 2.5) continue;
    const glm::dmat3 r = fluid.bodies().body(0).rotation();
    angle += glm::degrees(std::asin(-r[0].z));  // +θ about y takes x down
    fastest = std::max(fastest, glm::length(fluid.bodies().body(0).omega()));
    ++n;
  }
  angle /= n;
  const double water = double(fluid.count()) * fluid.mass() / kRho;
  const double want = flapAngle({pivot.x, pivot.z}, 2.0 * half.x, 2.0 * half.z, 2.0 * half.y, plank.density, water,
                                double(tank.x) * tank.y);
  std::printf("settled at %.2f degrees, the moments balance at %.2f; fastest %.3g rad/s\n", angle, want, fastest);
  EXPECT_NEAR(angle, want, 1.0);
  EXPECT_LT(fastest, 0.05) << "still swinging";
}
