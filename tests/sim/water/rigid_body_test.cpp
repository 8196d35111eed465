// Rigid bodies on the CPU (sim/water/rigid_body.h, body_contacts.h): mass properties from the
// particles, the integrator against its closed form, and contacts with the walls and between
// bodies that leave a dropped box resting flat, where it should be, without bouncing or sinking.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/water/body_contacts.h"
#include "sim/water/water_init.h"
#include "support/body_fixtures.h"

using namespace tidepool;
using water::BodyState, water::ContactBody, water::RigidBody;

namespace {

constexpr float kRadius = 0.005f;
constexpr double kDt = 1e-3;
const glm::dvec3 kGravity(0.0, 0.0, -9.81);

using test::dynamicBox;

// The largest |particle| + r about the own frame's origin: ContactBody::reach.
double reachOf(const std::vector<glm::vec4>& particles) {
  double reach = 0;
  for (const glm::vec4& q : particles) reach = std::max(reach, double(glm::length(glm::vec3(q))));
  return reach + kRadius;
}

// A body with its particles, as sim/water/bodies.h makes one.
struct Body {
  std::vector<glm::vec4> particles;
  double reach = 0;
  std::optional<RigidBody> body;
  explicit Body(const water::ObstacleParams& o) {
    const water::Obstacle shape(o, kRadius);
    particles = shape.particles();
    reach = reachOf(particles);
    body.emplace(water::massProperties(particles, shape.volume(particles.size()), o.density), o);
  }
  ContactBody contact() { return {&*body, &particles, reach, {}}; }
  double lowest() const {  // the lowest particle's centre, world z
    double z = 1e30;
    const water::ObstaclePose pose = body->pose();
    for (const glm::vec4& q : particles) z = std::min(z, double(pose.place(glm::vec3(q)).z));
    return z;
  }
};

water::Walls tank(glm::vec3 size) {
  water::Walls w;
  w.min = glm::vec3(0.0f);
  w.max = size;
  return w;
}

void steps(std::vector<Body*> bodies, int n, const water::Walls& walls) {
  std::vector<ContactBody> list;
  for (Body* b : bodies) list.push_back(b->contact());
  for (int i = 0; i < n; ++i) water::stepBodies(list, kDt, kGravity, walls, kRadius);
}

}  // namespace

// Mass = density × the box's volume exactly; the centre of mass is the box's middle within a
// particle radius (the HCP lattice is not symmetric about it); the inertia is the solid box's
// m(b² + c²)/3 within 10% (measured −2.2 to +6.9%): the lattice's outer layers lie up to r inside
// the faces and its particles are cubes of its volume per particle.
TEST(RigidBody, ABoxsMassIsItsDensityTimesItsVolumeAndItsInertiaNearlyTheSolidBoxs) {
  const glm::vec3 half(0.05f, 0.04f, 0.03f);
  const Body b(dynamicBox(half, glm::vec3(0.0f), 600.0f));
  const water::MassProperties& m = b.body->mass();
  const double a = half.x, bb = half.y, c = half.z;
  EXPECT_DOUBLE_EQ(m.mass, 600.0 * 8 * a * bb * c);
  EXPECT_LT(glm::length(m.centre), kRadius);
  const double want[3] = {m.mass * (bb * bb + c * c) / 3, m.mass * (a * a + c * c) / 3, m.mass * (a * a + bb * bb) / 3};
  for (int i = 0; i < 3; ++i) {
    std::printf("I%d %.4g, solid box %.4g (%+.1f%%)\n", i, m.inertia[i][i], want[i],
                100 * (m.inertia[i][i] / want[i] - 1));
    EXPECT_NEAR(m.inertia[i][i], want[i], 0.10 * want[i]) << "axis " << i;
  }
  EXPECT_LT(std::abs(m.inertia[0][1]), 0.02 * want[0]) << "the axes are principal";
}

// Falling freely, semi-implicit Euler: v_n = n g dt, z_n = z_0 + g dt² n(n+1)/2, to rounding.
TEST(RigidBody, AFreeFallIsSemiImplicitEuler) {
  Body b(dynamicBox({0.02f, 0.02f, 0.02f}, {0.5f, 0.5f, 0.8f}, 500.0f));
  const double z0 = b.body->state().position.z;
  const int n = 200;
  steps({&b}, n, tank(glm::vec3(1.0f)));
  EXPECT_NEAR(b.body->velocity().z, n * kGravity.z * kDt, 1e-12);
  EXPECT_NEAR(b.body->state().position.z, z0 + kGravity.z * kDt * kDt * n * (n + 1) / 2, 1e-12);
  EXPECT_EQ(b.body->velocity().x, 0.0);
  EXPECT_EQ(b.body->omega(), glm::dvec3(0.0));
}

// With no torque the angular momentum is kept exactly, the orientation stays a unit quaternion,
// and the kinetic energy ½ ω·L, which the first-order orientation update does not keep exactly,
// stays within 0.1% over 2000 steps of a tumbling spin (about no principal axis).
TEST(RigidBody, ATorqueFreeTumbleKeepsItsAngularMomentumAndEnergy) {
  Body b(dynamicBox({0.05f, 0.03f, 0.02f}, {0.5f, 0.5f, 0.5f}, 500.0f));
  BodyState& s = b.body->state();
  const glm::dvec3 L = b.body->mass().inertia * glm::dvec3(0.5, 1.0, 3.0);
  s.angularMomentum = L;
  const double energy = 0.5 * glm::dot(b.body->omega(), L);
  for (int i = 0; i < 2000; ++i) b.body->move(kDt);
  EXPECT_EQ(s.angularMomentum, L);
  EXPECT_NEAR(glm::length(s.orientation), 1.0, 1e-12);
  EXPECT_NEAR(0.5 * glm::dot(b.body->omega(), L), energy, 1e-3 * energy);
  EXPECT_GT(glm::length(glm::dvec3(b.body->omega()) - glm::dvec3(0.5, 1.0, 3.0)), 0.01) << "it tumbled";
}

// Dropped 2 cm onto the floor, a box stops there: its lowest particles a radius above the floor
// (within 2% of r), no speed or spin left to speak of, still level.
TEST(RigidBody, ABoxDroppedOnTheFloorComesToRestOnIt) {
  Body b(dynamicBox({0.04f, 0.03f, 0.02f}, {0.3f, 0.3f, 0.06f}, 800.0f));
  steps({&b}, 1000, tank({0.6f, 0.6f, 0.4f}));
  EXPECT_NEAR(b.lowest(), kRadius, 0.02 * kRadius);
  EXPECT_LT(glm::length(b.body->velocity()), 1e-3);
  EXPECT_LT(glm::length(b.body->omega()), 1e-2);
  EXPECT_GT(std::abs(b.body->state().orientation.w), std::cos(glm::radians(0.5) / 2)) << "it tipped";
}

// Dropped on one edge (turned 30° about x), a box falls over onto a face: its friction and the
// contacts' torque turn it; at rest its lowest particles lie a radius above the floor.
TEST(RigidBody, ABoxDroppedOnAnEdgeFallsFlat) {
  Body b(dynamicBox({0.04f, 0.04f, 0.02f}, {0.3f, 0.3f, 0.08f}, 800.0f, {30.0f, 0.0f, 0.0f}));
  steps({&b}, 3000, tank({0.6f, 0.6f, 0.4f}));
  const glm::dmat3 r = b.body->rotation();
  const double up = std::abs(r[2].z);  // the box's z axis against the world's
  EXPECT_GT(up, std::cos(glm::radians(1.0))) << "it did not settle on its broad face";
  EXPECT_NEAR(b.lowest(), kRadius, 0.05 * kRadius);
  EXPECT_LT(glm::length(b.body->velocity()), 1e-3);
}

// One box dropped onto another on the floor: the upper one rests on the lower, no particle of
// one closer to one of the other than 2r (within 5% of r; the layers nest where their lattices
// are offset), no faster than 1 mm/s, and the lower one does not sink into the floor.
TEST(RigidBody, ABoxDroppedOnAnotherRestsOnIt) {
  Body lower(dynamicBox({0.05f, 0.05f, 0.02f}, {0.3f, 0.3f, 0.03f}, 1500.0f));
  Body upper(dynamicBox({0.03f, 0.03f, 0.02f}, {0.3f, 0.3f, 0.1f}, 1500.0f));
  steps({&lower, &upper}, 2000, tank({0.6f, 0.6f, 0.4f}));
  EXPECT_NEAR(lower.lowest(), kRadius, 0.05 * kRadius);
  double closest = 1e30;
  const water::ObstaclePose a = lower.body->pose(), b = upper.body->pose();
  for (const glm::vec4& p : lower.particles)
    for (const glm::vec4& q : upper.particles)
      closest = std::min(closest, double(glm::distance(a.place(glm::vec3(p)), b.place(glm::vec3(q)))));
  EXPECT_NEAR(closest, 2 * kRadius, 0.05 * kRadius);
  EXPECT_GT(upper.lowest(), lower.lowest() + 0.04) << "it rests on top, not beside";
  EXPECT_LT(glm::length(upper.body->velocity()), 1e-3);
}

// A box hinged 4 cm from its centre is a compound pendulum: released 5° from hanging, it swings
// with the period 2π √(I_p / (m g d)), I_p = I_axis + m d² (within 0.3%; the small-angle period
// is 0.05% shorter than at 5°). The pivot's distance from the centre of mass is kept to 1e-9 m.
TEST(RigidBody, AHingedBoxSwingsWithTheCompoundPendulumsPeriod) {
  const double d = 0.04;
  water::ObstacleParams o = dynamicBox({0.03f, 0.02f, 0.01f}, {0.5f, 0.5f, 0.5f}, 700.0f);
  o.hingeAxis = {0.0f, 1.0f, 0.0f};
  o.hingeAt = {0.0f, 0.0f, float(d)};
  Body b(o);
  ASSERT_TRUE(b.body->hinge());
  // Start it hanging 5° to the side: turned about the pivot.
  const glm::dvec3 pivot = b.body->hinge()->pivot;
  const double start = glm::radians(5.0);
  const glm::dquat tilt = glm::angleAxis(start, glm::dvec3(0, 1, 0));
  BodyState& s = b.body->state();
  s.position = pivot + tilt * (s.position - pivot);
  s.orientation = tilt * s.orientation;
  const double arm = glm::distance(s.position, pivot);
  const water::MassProperties& m = b.body->mass();
  const double ip = m.inertia[1][1] + m.mass * arm * arm;
  const double want = 2 * glm::pi<double>() * std::sqrt(ip / (m.mass * 9.81 * arm));
  // Count the upward crossings of x through the pivot's over 10 periods.
  std::vector<double> crossings;
  double last = s.position.x - pivot.x, farthest = 0;
  std::vector<ContactBody> list{b.contact()};
  for (int i = 1; crossings.size() < 11 && i < 200000; ++i) {
    water::stepBodies(list, kDt, kGravity, tank(glm::vec3(1.0f)), kRadius);
    const double x = s.position.x - pivot.x;
    if (last < 0 && x >= 0) crossings.push_back(i * kDt - kDt * x / (x - last));
    last = x;
    farthest = std::max(farthest, std::abs(glm::distance(s.position, pivot) - arm));
  }
  ASSERT_EQ(crossings.size(), 11u);
  const double period = (crossings.back() - crossings.front()) / 10;
  std::printf("period %.5f s, compound pendulum %.5f s (%+.3f%%)\n", period, want, 100 * (period / want - 1));
  EXPECT_NEAR(period, want, 0.003 * want);
  EXPECT_LT(farthest, 1e-9);
}

// A plank hinged at one end, level, falls about its hinge onto the floor and rests there: its
// lowest particles a radius above the floor (within 2% of r), still, at the angle at which its
// particles, turned about the hinge, first touch the floor (within 0.2°).
TEST(RigidBody, APlankHingedAtOneEndFallsOntoTheFloorAndRests) {
  water::ObstacleParams o = dynamicBox({0.08f, 0.03f, 0.01f}, {0.3f, 0.3f, 0.06f}, 600.0f);
  o.hingeAxis = {0.0f, 1.0f, 0.0f};
  o.hingeAt = {-0.08f, 0.0f, 0.0f};
  Body b(o);
  steps({&b}, 3000, tank({0.6f, 0.6f, 0.4f}));
  EXPECT_NEAR(b.lowest(), kRadius, 0.02 * kRadius);
  EXPECT_LT(glm::length(b.body->omega()), 1e-3);
  // The angle at which the lowest particle, turned down about the hinge, is r above the floor.
  auto lowestAt = [&](double degrees) {
    double z = 1e30;
    for (const glm::vec4& q : b.particles) {
      const glm::dvec3 from(q.x + 0.08, q.y, q.z);  // from the hinge, level
      z = std::min(z, 0.06 + glm::dvec3(glm::angleAxis(glm::radians(degrees), glm::dvec3(0, 1, 0)) * from).z);
    }
    return z;
  };
  double lo = 0, hi = 90;
  for (int i = 0; i < 60; ++i) (lowestAt(0.5 * (lo + hi)) > kRadius ? lo : hi) = 0.5 * (lo + hi);
  const glm::dmat3 r = b.body->rotation();
  const double angle = glm::degrees(std::asin(-r[0].z));  // +θ about y takes x down
  std::printf("resting at %.3f degrees, touching the floor at %.3f\n", angle, lo);
  EXPECT_NEAR(angle, lo, 0.2);
}

// Pushed along its axis or through it, a hinged body cannot move, and the contacts do not ask it
// to: a box hinged about the vertical, resting on the floor, stays finite and still.
TEST(RigidBody, AContactAlongAHingesAxisLeavesItStill) {
  water::ObstacleParams o = dynamicBox({0.04f, 0.03f, 0.02f}, {0.3f, 0.3f, 0.0249f}, 800.0f);
  o.hingeAxis = {0.0f, 0.0f, 1.0f};
  Body b(o);
  const BodyState before = b.body->state();
  steps({&b}, 100, tank({0.6f, 0.6f, 0.4f}));
  EXPECT_EQ(b.body->state().position, before.position);
  EXPECT_EQ(b.body->omega(), glm::dvec3(0.0));
}

// A box dropped onto a fixed (kinematic) obstacle rests on it instead of falling through: no
// particle of one closer to one of the other than 2r (within 5% of r), the box above the
// obstacle's top, no faster than 1 mm/s. The obstacle does not move.
TEST(RigidBody, ABoxDroppedOnAFixedObstacleRestsOnIt) {
  water::ObstacleParams shelf = dynamicBox({0.06f, 0.06f, 0.02f}, {0.3f, 0.3f, 0.15f}, 1000.0f);
  shelf.dynamic = false;
  const water::Obstacle shape(shelf, kRadius);
  const std::vector<glm::vec4> shelfParticles = shape.particles();
  water::ObstaclePose shelfPose;
  shelfPose.centre = shelf.centre;
  Body upper(dynamicBox({0.03f, 0.03f, 0.02f}, {0.3f, 0.3f, 0.22f}, 800.0f));
  std::vector<ContactBody> list{upper.contact(), {nullptr, &shelfParticles, reachOf(shelfParticles), shelfPose}};
  for (int i = 0; i < 2000; ++i) water::stepBodies(list, kDt, kGravity, tank({0.6f, 0.6f, 0.4f}), kRadius);
  double closest = 1e30;
  const water::ObstaclePose b = upper.body->pose();
  for (const glm::vec4& p : shelfParticles)
    for (const glm::vec4& q : upper.particles)
      closest = std::min(closest, double(glm::distance(shelfPose.place(glm::vec3(p)), b.place(glm::vec3(q)))));
  std::printf("closest pair %.5f m (2r = %.5f), lowest particle %.4f m\n", closest, 2 * kRadius, upper.lowest());
  EXPECT_NEAR(closest, 2 * kRadius, 0.05 * kRadius);
  EXPECT_GT(upper.lowest(), 0.15 + 0.02 - kRadius) << "it sank into the shelf";
  EXPECT_LT(glm::length(upper.body->velocity()), 1e-3);
}
