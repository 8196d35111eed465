// Single-contact measurements of the balls model against DEM theory (shared/ACCURACY-REFERENCES.md,
// "DEM linear spring–dashpot"), shared by the tests and `tidepool sweep`:
//   restitution   one ball hits the floor at 1 m/s without gravity: e = v_out / v_in
// (the integrators' stability on an undamped contact is measured in tests/sim/balls/balls_physics_test.cpp).
#pragma once

#include "gl/shader_library.h"
#include "sim/balls/balls_params.h"

namespace tidepool::balls {
struct Stats;  // sim/balls/balls.h
}

namespace tidepool::balls {

struct Bounce {
  double restitution = -1;  // measured e (−1 when the ball never left the floor)
  int contactSteps = 0;     // steps in contact
};

// Spring-dashpot bounce with contact time t_c = 10 ms at t_c/dt = stepsPerContact.
Bounce measureBounce(gl::ShaderLibrary& shaders, Integrator integrator, float e, float stepsPerContact);

// Dam-break scales of a block fill (clamped to the domain): the column's width a and height h0, m.
struct ColumnScales {
  double width = 0, height = 0;
};
ColumnScales columnScales(const water::Setup& p);

// Surge front in units of a (as `tidepool validate --probe front`): the surface of the ball that is
// farthest along x among those within 2r of the floor, measured from the back wall. NaN: none.
double frontOverWidth(const water::Setup& p, const Stats& s, float radius);

}  // namespace tidepool::balls
