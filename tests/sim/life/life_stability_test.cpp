// Where particle life's integrators fail: two particles bound by the collision force oscillate
// harmonically about their equilibrium distance (sim/life/measure/life_measure.h). The largest stable
// ω·dt, found by bisection on the GPU, is compared with the limit of the model's one-step matrix
// with friction: euler (the article's symplectic Euler) f·h² < 2(1 + f), f = exp(−γ·dt), which
// friction raises above 2; verlet h < 2 at any friction.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>

#include "sim/life/measure/life_cpu.h"
#include "sim/life/measure/life_measure.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::life;

namespace {

using LifeTest = test::GlTest;

// Spectral radius of a 2x2 matrix [[a, b], [c, d]].
double spectralRadius(double a, double b, double c, double d) {
  const std::complex<double> mean = 0.5 * (a + d),
                             root = std::sqrt(std::complex<double>(mean * mean - (a * d - b * c)));
  return std::max(std::abs(mean + root), std::abs(mean - root));
}

// The one-step matrices of life_measure.h on (y, w/ω) at h = ω·dt, friction factor f.
double eulerRadius(double h, double f) { return spectralRadius(1 - f * h * h, f * h, -f * h, f); }
double verletRadius(double h, double f) {
  return spectralRadius(1 - h * h / 2, h, -f * h * (1 - h * h / 4), f * (1 - h * h / 2));
}

}  // namespace

TEST(LifeStabilityTheory, LimitIsWhereTheOneStepMatrixReachesSpectralRadiusOne) {
  EXPECT_EQ(eulerStableLimit(0.0), 2.0);
  EXPECT_NEAR(eulerStableLimit(0.2), 2.269, 0.001);
  EXPECT_TRUE(std::isinf(eulerStableLimit(0.6)));  // friction wins at every step
  // Without friction the stable side has |λ| = 1 exactly (up to round-off).
  const auto stable = [](double radius) { return radius < 1 + 1e-9; };
  for (double a : {0.0, 0.1, 0.2, 0.4}) {
    SCOPED_TRACE(a);
    const double limit = eulerStableLimit(a);
    for (double side : {0.995, 1.005}) {
      const double h = side * limit;
      EXPECT_EQ(stable(eulerRadius(h, std::exp(-a * h))), side < 1) << "euler at h = " << h;
      EXPECT_EQ(stable(verletRadius(side * 2, std::exp(-a * side * 2))), side < 1) << "verlet at h = " << side * 2;
    }
  }
}

TEST(LifeStabilityTheory, PairForceIsTheStatedSpringAboutItsEquilibrium) {
  // The CPU statement of the force pass: zero at d*, −k·(d − d*) per particle either side,
  // k = ω²/2, so that the separation oscillates at ω.
  const PairOscillator pair = pairOscillator(10.0);
  const double k = 0.5 * pair.omega * pair.omega;
  for (double offset : {0.0, -0.2, -0.01, 0.01, 0.2}) {
    const double d = pair.equilibrium + offset;
    std::vector<CpuParticle> two = {{{-0.5 * d, 0.0}, {0.0, 0.0}, 0}, {{0.5 * d, 0.0}, {0.0, 0.0}, 0}};
    const std::vector<CpuForce> f = cpuForces(pair.rules, two);
    EXPECT_NEAR(f[1].accel.x, -k * offset, 1e-3 * k * 0.2) << "offset " << offset;  // pushes the right one back
    EXPECT_NEAR(f[0].accel.x, k * offset, 1e-3 * k * 0.2);
  }
}

TEST_F(LifeTest, PairOscillatorLimitsMatchTheDerivationWithFriction) {
  // The model's default friction γ = 10/s at ω = 50/s: γ/ω = 0.2.
  const PairOscillator pair = pairOscillator(10.0);
  const double a = double(pair.rules.friction) / pair.omega;
  struct Case {
    Integrator integrator;
    double theory;
  };
  for (const Case c : {Case{Integrator::Euler, eulerStableLimit(a)}, Case{Integrator::Verlet, 2.0}}) {
    const char* name = kIntegratorNames[int(c.integrator)];
    const double measured = pairStableLimit(shaders(), pair, c.integrator, 0.002);
    std::printf("%s, friction/omega = %.2f: largest stable omega dt = %.4f (theory %.4f)\n", name, a, measured,
                c.theory);
    // The issue asks for 10%; the bisection (0.2%) and the growth bound's bias (< 0.5%) allow 1%.
    EXPECT_NEAR(measured / c.theory, 1.0, 0.01) << name;
  }
  // Without friction both are the undamped limit 2; with it, euler's lies measurably above.
  const double undamped = pairStableLimit(shaders(), pairOscillator(0.0), Integrator::Euler, 0.002);
  std::printf("euler, no friction: largest stable omega dt = %.4f (theory 2)\n", undamped);
  EXPECT_NEAR(undamped / 2.0, 1.0, 0.01);
}
