// Parameters of the fluid model (Position Based Fluids, Macklin & Müller, SIGGRAPH 2013): the
// water it shares with the balls model (domain, fill, walls, tap, obstacles, time step; the balls'
// radius is half the fluid's particle spacing) and the PBF solver's own keys, declared once for
// JSON and UI. SI units throughout: metres, seconds, kg/m³.
#pragma once

#include <cmath>
#include <cstddef>

#include "base/param.h"
#include "sim/balls/balls_params.h"

namespace tidepool::fluid {

struct Params {
  // What a fluid scene shares with a balls scene (the window switches between the two keeping it).
  // water.radius is spacing / 2 (set from `spacing` by resolvedWater()); contact laws are unused.
  balls::Params water = defaultWater();
  float spacing = 0.02f;        // d: distance between neighbouring particles at rest (cubic fill), m
  float restDensity = 1000.0f;  // ρ0, kg/m³
  float smoothing = 2.0f;       // h / d: the kernels' support in spacings
  int iterations = 4;           // solver iterations per step
  float relaxation = 0.01f;     // ε as a fraction of a resting particle's Σ|∇C|² (Macklin's CFM)
  float scorrK = 0.01f;         // tensile correction s_corr = −k (W(r)/W(Δq))^n, k as a compression (λ units)
  float scorrN = 4.0f;
  float scorrDq = 0.2f;     // Δq as a fraction of h
  float viscosity = 0.01f;  // XSPH c: the fraction of the neighbourhood's mean velocity blended in per step
  float vorticity = 0.0f;   // vorticity confinement ε_v (m/s); 0: off

  static balls::Params defaultWater();  // the balls defaults with a fluid's time step
  float h() const { return smoothing * spacing; }
};

void visit(ParamVisitor& v, Params& p);

// The water parameters with the radius of the spacing (what fills, obstacles and the tap use).
balls::Params resolvedWater(const Params& p);

// The fluid's spacing refined `factor` times (balls::refine for the rest: counts, dt, substeps,
// the resolution record). Throws Error; `p` is then unchanged.
void refine(Params& p, double factor);

}  // namespace tidepool::fluid
