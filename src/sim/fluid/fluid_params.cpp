#include "sim/fluid/fluid_params.h"

namespace tidepool::fluid {

balls::Params Params::defaultWater() {
  balls::Params w;
  w.dt = 1.0f / 600.0f;
  w.substeps = 10;
  w.tapMax = 20000;
  return w;
}

void visit(ParamVisitor& v, Params& p) {
  balls::Params& w = p.water;
  if (v.beginGroup({"particles", "Particles", "spacing, domain and initial water (re-creates the particles)"})) {
    v.real({"spacing", "Spacing", "d: particle distance at rest, m"}, p.spacing, 2e-4f, 1.0f);
    balls::visitFill(v, w);
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
    v.real({"dt", "Time step", "s"}, w.dt, 1e-6f, 0.1f);
    v.integer({"substeps", "Substeps", "steps per frame"}, w.substeps, 1, 1000);
    v.vector({"gravity", "Gravity", "m/s^2"}, w.gravity, -1000.0f, 1000.0f);
    v.real({"damping", "Damping", "1/s, frame-rate independent"}, w.damping, 0.0f, 1000.0f);
    v.real({"foam_gain", "Foam gain", "per m of travel"}, w.foamGain, 0.0f, 1000.0f);
    v.real({"foam_decay", "Foam decay", "factor per 0.5 ms"}, w.foamDecay, 0.5f, 1.0f);
    v.endGroup();
  }
  if (v.beginGroup({"walls", "Walls", "piston and domain rotation"})) {
    balls::visitWalls(v, w);
    v.endGroup();
  }
  if (v.beginGroup({"tap", "Tap", "emits particles over time"})) {
    balls::visitTap(v, w);
    v.endGroup();
  }
  balls::visitObstacles(v, w);
}

balls::Params resolvedWater(const Params& p) {
  balls::Params w = p.water;
  w.radius = 0.5f * p.spacing;
  w.latticeScaling = false;
  return w;
}

void refine(Params& p, double factor) {
  balls::Params water = p.water;
  balls::refine(water, factor);
  p.water = water;
  p.spacing = float(double(p.spacing) / factor);
}

}  // namespace tidepool::fluid
