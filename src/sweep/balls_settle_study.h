// The balls-settle measurement (balls_settle_study.cpp), also run by the tests of "method": "auto"
// on the settings it picks from the study's rows.
#pragma once

#include "gl/shader_library.h"
#include "sim/balls/balls_params.h"

namespace tidepool::sweep {

struct Settle {
  double maxOverlap = 0;   // largest overlap after the settle, fraction of r
  double energyDrift = 0;  // (E_end − E_rigid) / (N·g·r): E_rigid is the stack's starting potential energy
  bool stable = true;      // no NaN, none lost or outside the walls, overlap at most r
  double costMsPerSimS = 0;
};

// A block `across` x `across` balls wide and six deep (r = 1 cm) in a simple cubic stack that fits
// its box, released at rest under g = 9.81 m/s² and settled for 0.25 s with damping 60/s, at
// step dt; spring-dashpot contacts last t_c = 20·dt (e = 0.5). The study runs across = 200.
Settle measureSettle(gl::ShaderLibrary& shaders, balls::Contact contact, balls::Integrator integrator, double dt,
                     int across = 7);
constexpr double kSettleStepsPerContact = 20;  // t_c / dt of the study's spring-dashpot rows

}  // namespace tidepool::sweep
