// Integrator accuracy and stability of the swarm (shared by the tests and `tidepool sweep`).
//   orbit        one attractor of strength s = 1 at the origin, a ring of 64 particles at radius
//                0.5 with the circular speed √s, ε = 0, no friction, no walls. The energy
//                E = |v|²/2 − s·ln|x| is conserved exactly, so the error of an integrator is
//                max |ΔE|/s over the run.
//   oscillator   the core of a softened attractor: for |x|² ≪ ε the force s·d/(|d|² + ε) is
//                −(s/ε)·x, a harmonic oscillator of ω = √(s/ε) (shared/ACCURACY-REFERENCES.md,
//                "Time integrators": symplectic Euler and Verlet stable while ω·dt < 2, RK4 while
//                ω·dt ≤ 2√2, explicit Euler never).
#pragma once

#include "gl/shader_library.h"
#include "sim/swarm/swarm_params.h"

namespace tidepool::sim {

// max |ΔE| / s over `orbits` orbits at `stepsPerOrbit` steps per orbit (sampled every step).
double orbitEnergyError(gl::ShaderLibrary& shaders, Integrator integrator, Storage storage, int stepsPerOrbit,
                        int orbits = 10);

// Simulated seconds of one orbit of that setup.
double orbitPeriod();

// The oscillator: s = 1 at the origin with the default softening ε = 0.01 (ω = 10/s), no gravity,
// friction or walls; 8 particles at amplitude A = 10⁻³·√ε (so that |x|²/ε stays below 4·10⁻⁴ up to
// the growth bound below), along 8 directions at 8 phases of the oscillation.
double oscillatorOmega();  // 1/s

// Largest |x| / A over `periods` periods of ω at step ω·dt = omegaDt (1: the amplitude is kept;
// more: energy gained). Stops early and returns infinity on NaN or past kOscillatorGrowthBound.
double oscillatorGrowth(gl::ShaderLibrary& shaders, Integrator integrator, double omegaDt, int periods);

inline constexpr double kOscillatorGrowthBound = 20;  // |x| / A beyond this: unstable
inline constexpr int kOscillatorPeriods = 50;         // of ω, the run that decides stability

// Largest ω·dt at which the oscillator's growth stays below kOscillatorGrowthBound over
// kOscillatorPeriods periods, by bisection to a relative width of `tolerance` over [0.5, 4]
// (0 when ω·dt = 0.5 already fails).
double oscillatorStableLimit(gl::ShaderLibrary& shaders, Integrator integrator, double tolerance = 0.01);

}  // namespace tidepool::sim
