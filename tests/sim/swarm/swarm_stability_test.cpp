// Where the swarm's integrators fail: the core of a softened attractor is a harmonic oscillator
// (force s·d/(|d|² + ε) ≈ −(s/ε)·x for |x|² ≪ ε, ω = √(s/ε)), and the largest stable ω·dt of each
// integrator, found by bisection on the GPU (sim/swarm/measure/swarm_measure.h), is compared with the
// limit of its one-step matrix (shared/ACCURACY-REFERENCES.md, "Time integrators"): symplectic Euler and velocity
// Verlet 2, classical RK4 2√2, explicit Euler none.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "sim/swarm/measure/swarm_measure.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::sim;

namespace {

using SwarmTest = test::GlTest;

}  // namespace

TEST_F(SwarmTest, SoftenedCoreOscillatorLimitsMatchTheory) {
  struct Case {
    Integrator integrator;
    double theory;
  };
  for (const Case c : {Case{Integrator::SymplecticEuler, 2.0}, Case{Integrator::Verlet, 2.0},
                       Case{Integrator::Rk4, 2.0 * std::numbers::sqrt2}}) {
    const char* name = kIntegratorNames[int(c.integrator)];
    const double measured = oscillatorStableLimit(shaders(), c.integrator, 0.002);
    std::printf("%s: largest stable omega dt = %.4f (theory %.4f)\n", name, measured, c.theory);
    // The issue asks for 10%; the bisection (0.2%) and the growth bound's bias (< 0.5%) allow 1%.
    EXPECT_NEAR(measured / c.theory, 1.0, 0.01) << name;
  }
}

TEST_F(SwarmTest, ExplicitEulerGrowsAtEveryStep) {
  // |R| = √(1 + (ω·dt)²) per step: over 10 periods at 200 steps per period the amplitude grows
  // by (1 + h²)^1000 = e^0.99 ≈ 2.7, and the bisection finds no stable ω·dt at all.
  const double h = 2.0 * std::numbers::pi / 200;
  const double growth = oscillatorGrowth(shaders(), Integrator::ExplicitEuler, h, 10);
  std::printf("explicit Euler: amplitude x %.3f over 10 periods at omega dt = %.4f\n", growth, h);
  EXPECT_NEAR(growth, std::pow(1.0 + h * h, 1000.0), 0.1);
  EXPECT_EQ(oscillatorStableLimit(shaders(), Integrator::ExplicitEuler, 0.05), 0.0);
  // The symplectic methods keep it at the same step (the amplitude stays within O(h) of 1).
  for (Integrator integrator : {Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4})
    EXPECT_LT(oscillatorGrowth(shaders(), integrator, h, 10), 1.05) << kIntegratorNames[int(integrator)];
}
