// Single-contact measurements of the balls model against DEM theory (shared/ACCURACY-REFERENCES.md,
// "DEM linear spring–dashpot"), shared by the tests and `tidepool sweep`:
//   restitution   one ball hits the floor at 1 m/s without gravity: e = v_out / v_in
//   stability     an undamped contact (e = 1) oscillates with ω0 = π/t_c; symplectic Euler and
//                 Verlet are stable while ω0·dt < 2, i.e. dt < 2·t_c/π ≈ 0.64·t_c; explicit
//                 Euler gains energy at any dt
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

// Largest |overlap − equilibrium| / equilibrium over `periods` periods of an undamped contact
// oscillation (a ball on the floor under gravity pushed in to twice its equilibrium overlap, so
// 1 means the amplitude is kept; more is energy gained). dtOverTc = dt / t_c.
double contactAmplitudeGrowth(gl::ShaderLibrary& shaders, Integrator integrator, double dtOverTc, int periods);

// Growth of a small undamped contact oscillation: its amplitude over the last period divided by
// that over the first (1: kept; more: energy gained; infinity: blown up).
double contactGrowthRatio(gl::ShaderLibrary& shaders, Integrator integrator, double dtOverTc, int periods);

// Largest dt / t_c at which the undamped contact's amplitude grows less than 1.5x over 12
// periods, by bisection to a relative width of `tolerance` (0 when t_c/20 already fails).
double stableStepLimit(gl::ShaderLibrary& shaders, Integrator integrator, double tolerance = 0.01);

// Dam-break scales of a block fill (clamped to the domain): the column's width a and height h0, m.
struct ColumnScales {
  double width = 0, height = 0;
};
ColumnScales columnScales(const water::Setup& p);

// Surge front in units of a (as `tidepool validate --probe front`): the surface of the ball that is
// farthest along x among those within 2r of the floor, measured from the back wall. NaN: none.
double frontOverWidth(const water::Setup& p, const Stats& s, float radius);

}  // namespace tidepool::balls
