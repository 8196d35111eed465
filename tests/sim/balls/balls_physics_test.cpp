// Physics of the balls against theory (shared/ACCURACY-REFERENCES.md §2.2): free fall, the
// spring-dashpot restitution, momentum in a head-on collision, energy behaviour of the
// integrators on an undamped contact, and a settled column.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/balls/balls.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::balls;

namespace {

class BallsPhysics : public test::GlTest {};

Params oneBallBox() {
  Params p;
  p.fill = Fill::None;
  p.radius = 0.01f;
  p.domainMin = glm::vec3(0.0f);
  p.domainMax = glm::vec3(1.0f);
  p.contact = Contact::SpringDashpot;
  p.integrator = Integrator::SymplecticEuler;
  p.substeps = 1;
  return p;
}

// Measured restitution of one ball hitting the floor at 1 m/s without gravity, and the contact
// duration in steps.
std::pair<double, int> bounce(gl::ShaderLibrary& shaders, Integrator integrator, float e, int stepsPerContact) {
  Params p = oneBallBox();
  p.gravity = glm::vec3(0.0f);
  p.integrator = integrator;
  p.restitution = e;
  p.contactTime = 0.01f;
  p.dt = p.contactTime / float(stepsPerContact);
  Balls b(shaders, p);
  b.upload({glm::vec4(0.5f, 0.5f, p.radius + 0.01f, 1.0f)}, {glm::vec4(0.0f, 0.0f, -1.0f, 0.0f)});
  int inContact = 0;
  for (int i = 0; i < 20 * stepsPerContact; ++i) {
    b.stepOnce();
    const glm::vec4 x = b.downloadPositions()[0];
    if (x.z < p.radius)
      ++inContact;
    else if (inContact > 0)
      return {double(b.downloadVelocities()[0].z) / 1.0, inContact};
  }
  return {-1.0, inContact};
}

}  // namespace

TEST_F(BallsPhysics, FreeFallFollowsTheParabolaBeforeContact) {
  Params p = oneBallBox();
  p.dt = 1e-3f;
  Balls b(shaders(), p);
  const double z0 = 0.8, g = 9.81;
  b.upload({glm::vec4(0.5f, 0.5f, float(z0), 1.0f)}, {glm::vec4(0.0f)});
  for (int n = 1; n <= 300; ++n) {  // 0.3 s: still above the floor
    b.stepOnce();
    const double t = n * double(p.dt), z = b.downloadPositions()[0].z;
    // Symplectic Euler is exact up to a first-order drift: z_n = z0 − g·dt²·n(n+1)/2.
    ASSERT_NEAR(z, z0 - g * p.dt * p.dt * n * (n + 1) / 2.0, 2e-5) << "step " << n;
    ASSERT_NEAR(z, z0 - 0.5 * g * t * t, g * p.dt * t + 1e-5) << "step " << n;
  }
}

TEST_F(BallsPhysics, SpringDashpotRestitutionMatchesAt50StepsPerContactAndConverges) {
  for (float e : {0.5f, 0.9f}) {
    const auto [e50, steps50] = bounce(shaders(), Integrator::SymplecticEuler, e, 50);
    EXPECT_NEAR(e50 / e, 1.0, 0.02) << "e = " << e << ": measured " << e50;
    EXPECT_NEAR(steps50, 50, 2) << "the contact lasts t_c";
    const double err20 = std::abs(bounce(shaders(), Integrator::SymplecticEuler, e, 20).first / e - 1.0);
    const double err50 = std::abs(e50 / e - 1.0);
    const double err100 = std::abs(bounce(shaders(), Integrator::SymplecticEuler, e, 100).first / e - 1.0);
    EXPECT_LT(err50, err20);
    EXPECT_LT(err100, err50) << "first order: the error shrinks with dt";
  }
  const auto [verlet, steps] = bounce(shaders(), Integrator::VelocityVerlet, 0.9f, 50);
  EXPECT_NEAR(verlet / 0.9, 1.0, 0.02) << "velocity Verlet: " << verlet;
  (void)steps;
}

TEST_F(BallsPhysics, HeadOnCollisionConservesMomentumAndSwapsEqualMasses) {
  for (float e : {1.0f, 0.5f}) {
    Params p = oneBallBox();
    p.gravity = glm::vec3(0.0f);
    p.restitution = e;
    p.contactTime = 0.01f;
    p.dt = 2e-4f;
    Balls b(shaders(), p);
    b.upload({glm::vec4(0.45f, 0.5f, 0.5f, 1.0f), glm::vec4(0.55f, 0.5f, 0.5f, 1.0f)},
             {glm::vec4(1.0f, 0.0f, 0.0f, 0.0f), glm::vec4(-1.0f, 0.0f, 0.0f, 0.0f)});
    for (int i = 0; i < 500; ++i) {
      b.stepOnce();
      const std::vector<glm::vec4> v = b.downloadVelocities();
      ASSERT_NEAR(double(v[0].x) + v[1].x, 0.0, 1e-6) << "momentum, step " << i;
    }
    const std::vector<glm::vec4> x = b.downloadPositions(), v = b.downloadVelocities();
    const int left = x[0].x < x[1].x ? 0 : 1;
    EXPECT_NEAR(v[left].x, -e, 0.02 * e) << "e = " << e;
    EXPECT_NEAR(v[1 - left].x, e, 0.02 * e);
  }
}

TEST_F(BallsPhysics, ExplicitEulerGainsEnergyOnAnUndampedContactTheOthersDoNot) {
  // A ball resting on the floor under gravity, pushed in to twice its equilibrium overlap: it
  // oscillates in contact (undamped, e = 1) with an amplitude of one equilibrium overlap.
  auto amplitudeGrowth = [&](Integrator integrator) {
    Params p = oneBallBox();
    p.restitution = 1.0f;
    p.contactTime = 0.01f;  // half period of the contact oscillation
    p.dt = p.contactTime / 25;
    p.integrator = integrator;
    const double omega2 = springPerMass(p);  // wall: m_eff = m
    const double equilibrium = 9.81 / omega2;
    Balls b(shaders(), p);
    b.upload({glm::vec4(0.5f, 0.5f, float(p.radius - 2 * equilibrium), 1.0f)}, {glm::vec4(0.0f)});
    double maxDeviation = 0;
    for (int i = 0; i < 250; ++i) {  // five periods
      b.stepOnce();
      const double overlap = p.radius - b.downloadPositions()[0].z;
      maxDeviation = std::max(maxDeviation, std::abs(overlap - equilibrium));
    }
    return maxDeviation / equilibrium;  // 1 when the amplitude is kept
  };
  const double explicitEuler = amplitudeGrowth(Integrator::ExplicitEuler);
  const double symplectic = amplitudeGrowth(Integrator::SymplecticEuler);
  const double verlet = amplitudeGrowth(Integrator::VelocityVerlet);
  EXPECT_GT(explicitEuler, 1.5) << "explicit Euler must gain energy";
  EXPECT_LT(symplectic, 1.15) << "symplectic Euler stays bounded";
  EXPECT_LT(verlet, 1.05) << "velocity Verlet stays bounded";
}

// About 8k balls settling in a packed column. The spring-dashpot law is stiff by construction
// (t_c = 2 ms); the seed's penalty law corrects 0.48·overlap per step as a velocity, so its
// stiffness is 0.48/dt per unit mass: it is run as the seed runs it, with the seed's gravity
// (0.9 m/s²) and a short step, where its overlaps are small too.
TEST_F(BallsPhysics, SettledColumnKeepsEveryBallWithSmallOverlaps) {
  for (Contact contact : {Contact::SpringDashpot, Contact::Penalty}) {
    SCOPED_TRACE(kContactNames[int(contact)]);
    const bool penalty = contact == Contact::Penalty;
    Params p;
    p.radius = 0.01f;
    p.domainMin = glm::vec3(0.0f);
    p.domainMax = penalty ? glm::vec3(0.72f, 0.72f, 0.3f) : glm::vec3(0.34f, 0.34f, 0.7f);
    p.fill = Fill::Block;
    p.fillMin = p.domainMin;
    p.fillMax = penalty ? glm::vec3(0.72f, 0.72f, 0.1f) : glm::vec3(0.34f, 0.34f, 0.42f);
    p.contact = contact;
    p.gravity = glm::vec3(0.0f, 0.0f, penalty ? -0.9f : -9.81f);
    p.contactTime = 0.002f;
    p.restitution = 0.3f;
    p.dt = penalty ? 5e-5f : 1e-4f;
    p.damping = penalty ? 5.0f : 2.0f;
    p.substeps = 100;
    Balls b(shaders(), p);
    const std::size_t n = b.count();
    ASSERT_GT(n, 7000u);
    gl::GpuProfiler profiler;
    for (int frame = 0; frame < 20; ++frame) b.step(profiler);
    const Stats s = b.stats();
    EXPECT_EQ(s.count, n);
    EXPECT_EQ(s.nonFinite, 0u);
    EXPECT_EQ(s.outside, 0u);
    EXPECT_LT(s.maxOverlap, 0.05) << "max overlap, fraction of r (mean " << s.meanOverlap << ")";
  }
}
