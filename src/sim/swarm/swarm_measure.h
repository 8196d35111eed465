// Integrator accuracy of the swarm on a circular orbit (shared by `tidepool sweep`): one attractor
// of strength s = 1 at the origin, a ring of 64 particles at radius 0.5 with the circular speed
// √s, ε = 0, no friction, no walls. The energy E = |v|²/2 − s·ln|x| is conserved exactly, so the
// error of an integrator is max |ΔE|/s over the run.
#pragma once

#include "gl/shader_library.h"
#include "sim/swarm/swarm_params.h"

namespace tidepool::sim {

// max |ΔE| / s over `orbits` orbits at `stepsPerOrbit` steps per orbit (sampled every step).
double orbitEnergyError(gl::ShaderLibrary& shaders, Integrator integrator, Storage storage, int stepsPerOrbit,
                        int orbits = 10);

// Simulated seconds of one orbit of that setup.
double orbitPeriod();

}  // namespace tidepool::sim
