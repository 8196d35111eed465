// Where each contact law of the balls fails, with each integrator (shared by the tests and
// `tidepool sweep balls-stability`): one ball resting under gravity on one fixed particle, the
// linear contact of every law. With y the ball's height above its equilibrium, u = v·dt, and the
// contact acting as a per-step velocity change, each law is a per-step stiffness h² = (ω·dt)²
// and a per-step velocity factor f:
//   spring-dashpot (e = 1)   h² = k1·dt²           f = 1     (k1 = π²/t_c²: ω = π/t_c)
//   penalty                  h² = factor·dt        f = 1     (Δv = factor·δ per step)
//   cuda-sample              h² = spring·dt        f = 1 − c (Δv = spring·δ − c·v per step)
// The penalty and CUDA laws divide by dt, so their stiffness grows as the step shrinks and their
// limit is on factor·dt or spring·dt. The one-step matrices on (y, u):
//   symplectic Euler  (u' = f·u − h²·y; y' = y + u')   [[1 − h², f], [−h², f]]
//   explicit Euler    (y' = y + u; u' = f·u − h²·y)    [[1, 1], [−h², f]]
//   velocity Verlet   (the model's drift, then force and kick from the half-step velocity) is,
//                     on y and the half-step u, the symplectic Euler map above
// Jury (|trace| < 1 + det, det < 1): symplectic Euler and Verlet are stable while
// h² < 2·(1 + f) (h < 2 undamped; h < 1.990 for the CUDA sample's c = 0.02), explicit Euler while
// h² < 1 − f: never when undamped, h < √c = 0.141 with the CUDA sample's damping.
#pragma once

#include "gl/shader_library.h"
#include "sim/balls/balls_params.h"

namespace tidepool::balls {

// The resting contact's scene at per-step stiffness ω·dt = omegaDt for `law` (the model's default
// law parameters; e = 1 and t_c = 10 ms for the spring): dt from omegaDt, gravity chosen so that
// the equilibrium overlap is r/10 at every dt, no damping but the law's own.
Params restingContact(Contact law, Integrator integrator, double omegaDt);

// The resting ball pushed 2% of its equilibrium overlap further in, from rest, for `steps` steps:
//   growth   the largest |y| over the last quarter over that over the first (about 1 when kept,
//            less when damped, more when growing; decides stability)
//   largest  the largest |y| over the push (symplectic Euler's orbit stretches toward 1/√(1 − h²/4))
// Both infinity on NaN or past kRestingBlowUp times the push.
struct RestingRun {
  double growth = 0, largest = 0;
};
RestingRun restingRun(gl::ShaderLibrary& shaders, Contact law, Integrator integrator, double omegaDt, int steps = 2000);

inline constexpr double kRestingBlowUp = 100;
inline constexpr double kRestingGrowthBound = 1.2;  // growth at or beyond this: unstable

// Largest ω·dt in [0.05, 4] whose growth over `steps` steps stays below kRestingGrowthBound, by
// bisection to a relative width of `tolerance` (0 when ω·dt = 0.05 already grows).
double restingStableLimit(gl::ShaderLibrary& shaders, Contact law, Integrator integrator, double tolerance = 0.01,
                          int steps = 2000);

// The derivation's limit on ω·dt (see above); 0 where no step is stable.
double restingTheoryLimit(Contact law, Integrator integrator);

// The other way these two laws fail: being divided by dt, they soften as the step grows, and the
// overlap of a loaded contact grows with it. A ball released at rest just touching the fixed
// particle under g = 9.81 m/s² (symplectic Euler, r = 1 cm) overshoots its equilibrium overlap
// δ* = g·dt/factor (penalty) or g·dt/spring (cuda-sample) by the response of its oscillator:
//   penalty      undamped, max overlap 2·δ*, past r from dt = factor·r/(2g) = 0.489 ms
//   cuda-sample  ζ = c/(2·ω·dt) = c/(2·√(spring·dt)), max overlap δ*·(1 + exp(−π·ζ/√(1 − ζ²))),
//                past r from dt = 0.477 ms (ζ = 0.65 there)
// Largest dt (s) whose largest overlap over one period stays below r, by bisection over
// [10 µs, 10 ms] to a relative width of `tolerance`; and the derivation's value.
double overlapStepLimit(gl::ShaderLibrary& shaders, Contact law, double tolerance = 0.01);
double overlapStepTheory(Contact law);

// dt at per-step stiffness omegaDt, and the law's velocity factor per step (f above).
double restingStep(Contact law, double omegaDt);
double restingVelocityFactor(Contact law);

}  // namespace tidepool::balls
