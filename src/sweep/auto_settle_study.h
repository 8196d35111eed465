// PROVISIONAL: a minimal settling-column measurement so that "method": "auto" can pick a balls
// contact law and time step for a maxOverlap / energyDrift bound before the balls-settle study
// lands (issue 10 part 1). `tidepool sweep balls-settle-provisional --ship` writes
// assets/accuracy/balls-settle-provisional.csv, which auto reads (with a warning) only while
// assets/accuracy/balls-settle.csv is missing. Delete this file, its .cpp and that CSV once
// `tidepool sweep balls-settle --ship` has run on the GPU machine.
#pragma once

#include "gl/shader_library.h"
#include "sim/balls/balls_params.h"

namespace tidepool::sweep {

struct Settle {
  double maxOverlap = 0;   // largest overlap of two balls (or a ball and a wall) over the run, fraction of r
  double energyDrift = 0;  // max |E(t) - E(T/2)| / E(0) over the second half (E = kinetic + potential)
  bool stable = true;      // no NaN, no ball outside the walls, overlap below r
};

// A column of about 450 balls (r = 1 cm, HCP block 10 x 10 x 30 cm) released touching in a
// 10 cm x 10 cm tube, t_c = 2 ms, e = 0.5 (the penalty law ignores both), `seconds` of settling at step dt.
Settle measureSettle(gl::ShaderLibrary& shaders, balls::Contact contact, balls::Integrator integrator, double dt,
                     double seconds = 0.5);

}  // namespace tidepool::sweep
