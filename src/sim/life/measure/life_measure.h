// Where particle life's integrators fail (shared by the tests and `tidepool sweep`): two particles
// of one species bound by the collision force. Below the collision radius Rc the pair force's
// magnitude (life/pair_force.glsl, > 0 attracts) is linear in the distance d,
//   M(d) = s·(1 − d/R) − c·(1 − d/Rc) = k·(d − d*),   k = c/Rc − s/R,   d* = (c − s)/k,
// and both particles move (mass 1), so the separation obeys d'' = −2·M(d): a harmonic oscillator
// of ω² = 2k while d stays in (0, Rc). With y = d − d*, w = ḋ/ω, h = ω·dt and the model's friction
// factor f = exp(−γ·dt) per step, the one-step matrices of the model's updates are
//   euler  (v = (v + a·dt)·f; p += v·dt):      [[1 − f·h², f·h], [−f·h, f]]
//   verlet (drift; kick; v *= f):              [[1 − h²/2, h], [−f·h·(1 − h²/4), f·(1 − h²/2)]]
// both of determinant f, so (Jury: |trace| < 1 + det) euler is stable while f·h² < 2·(1 + f), a
// limit that friction raises above 2, and verlet, of trace (1 + f)(1 − h²/2), while h < 2 for any f.
#pragma once

#include "gl/shader_library.h"
#include "sim/life/life_params.h"
#include "sim/life/life_rules.h"

namespace tidepool::life {

struct PairOscillator {
  double omega = 0;        // 1/s, of the separation
  double equilibrium = 0;  // d*, world units
  double amplitude = 0;    // |d − d*| at the start (at rest), world units
  Rules rules;             // one species, two particles, walls far away
};

// ω = 50/s with R = 2, Rc = 1, d* = 0.5 (s = 1250, c = 1875), amplitude 0.01 (so that it stays in
// the linear range up to the growth bound below), at `friction` γ (1/s; 10 is the model's default).
PairOscillator pairOscillator(double friction);

// Largest |d − d*| / amplitude over `periods` periods of ω at ω·dt = omegaDt. Stops early and
// returns infinity on NaN or past kPairGrowthBound.
double pairGrowth(gl::ShaderLibrary& shaders, const PairOscillator& pair, Integrator integrator, double omegaDt,
                  int periods);

inline constexpr double kPairGrowthBound = 20;  // |d − d*| / amplitude beyond this: unstable
inline constexpr int kPairPeriods = 50;         // of ω, the run that decides stability

// Largest ω·dt at which the growth stays below kPairGrowthBound over kPairPeriods periods, by
// bisection to a relative width of `tolerance` over [1, 4] (0 when ω·dt = 1 already fails).
double pairStableLimit(gl::ShaderLibrary& shaders, const PairOscillator& pair, Integrator integrator,
                       double tolerance = 0.01);

// Theory: the largest ω·dt of the euler update at friction γ = frictionOverOmega·ω, the first root
// of h² = 2·(exp(γ·h/ω) + 1): 2 without friction, 2.269 at γ/ω = 0.2; infinity when γ/ω > 0.4913,
// where friction keeps f·h² below 2·(1 + f) at every step. Verlet's limit is 2 whatever the friction.
double eulerStableLimit(double frictionOverOmega);

}  // namespace tidepool::life
