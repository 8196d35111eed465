#include "sim/fluid/fluid_params.h"
#include "sim/water/probes.h"

namespace tidepool::fluid {

void visit(ParamVisitor& v, Params& p) {
  if (v.beginGroup({"particles", "Particles", "spacing, domain and initial water (re-creates the particles)"})) {
    float spacing = p.spacing();
    v.real({"spacing", "Spacing", "d: particle distance at rest, m"}, spacing, 2e-4f, 1.0f);
    p.setSpacing(spacing);
    water::visitFill(v, p);
    v.endGroup();
  }
  if (v.beginGroup({"solver", "Solver", "position-based fluid: density constraint, iterations, viscosity"})) {
    v.real({"rest_density", "Rest density", "rho0, kg/m^3"}, p.restDensity, 1.0f, 1e5f);
    v.real({"smoothing", "Smoothing", "h / spacing: kernel support (above 1)"}, p.smoothing, 1.01f, 4.0f);
    v.integer({"iterations", "Iterations", "density solver iterations per step"}, p.iterations, 1, 100);
    v.real({"relaxation", "Relaxation", "epsilon, fraction of a resting particle's constraint gradient"}, p.relaxation,
           1e-6f, 10.0f);
    v.real({"scorr_k", "s_corr k", "tensile-instability correction strength"}, p.scorrK, 0.0f, 1.0f);
    v.real({"scorr_n", "s_corr n", "exponent"}, p.scorrN, 1.0f, 8.0f);
    v.real({"scorr_dq", "s_corr dq", "delta q, fraction of h"}, p.scorrDq, 0.0f, 0.99f);
    v.real({"viscosity", "Viscosity", "XSPH c: fraction of the neighbours' velocity blended per step"}, p.viscosity,
           0.0f, 1.0f);
    v.real({"vorticity", "Vorticity", "confinement epsilon (0: off)"}, p.vorticity, 0.0f, 100.0f);
    v.endGroup();
  }
  if (v.beginGroup({"engine", "Engine", "time step, gravity"})) {
    water::visitEngine(v, p, 0.1f);
    water::visitFoam(v, p);
    v.real({"spray_density", "Spray density", "rho/rho0 under which a particle turns to foam, as spray (0: off)"},
           p.sprayDensity, 0.0f, 1.0f);
    v.endGroup();
  }
  if (v.beginGroup({"walls", "Walls", "piston and domain rotation"})) {
    water::visitWalls(v, p);
    v.endGroup();
  }
  if (v.beginGroup({"tap", "Tap", "emits particles over time"})) {
    water::visitTap(v, p);
    v.endGroup();
  }
  water::visitObstacles(v, p);
  water::visitProbes(v, p.probes);
}

}  // namespace tidepool::fluid
