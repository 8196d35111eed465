// Parameters of the fluid model (Position Based Fluids, Macklin & Müller, SIGGRAPH 2013): the
// water (sim/water/setup.h: domain, fill, walls, tap, obstacles, engine step; the particle size,
// read and written as the spacing d = 2r) and the PBF solver's own keys, declared once for JSON
// and UI. SI units throughout: metres, seconds, kg/m³.
#pragma once

#include "base/param.h"
#include "sim/water/setup.h"

namespace tidepool::fluid {

// The water setup is a base (as balls::Params'), with a fluid's time step by default.
struct Params : water::Setup {
  float restDensity = 1000.0f;  // ρ0, kg/m³
  float smoothing = 2.0f;       // h / d: the kernels' support in spacings
  int iterations = 4;           // solver iterations per step
  float relaxation = 0.01f;     // ε as a fraction of a resting particle's Σ|∇C|² (Macklin's CFM)
  float scorrK = 0.01f;         // tensile correction s_corr = −k (W(r)/W(Δq))^n, k as a compression (λ units)
  float scorrN = 4.0f;
  float scorrDq = 0.2f;        // Δq as a fraction of h
  float viscosity = 0.01f;     // XSPH c: the fraction of the neighbourhood's mean velocity blended in per step
  float vorticity = 0.0f;      // vorticity confinement ε_v (m/s); 0: off
  float sprayDensity = 0.24f;  // ρ/ρ0 under which a particle turns (partly) to foam, as spray; 0: off

  Params() {
    dt = 1.0f / 600.0f;
    substeps = 10;
  }
  // d: distance between neighbouring particles at rest (cubic fill), m
  float spacing() const { return water::spacing(radius); }
  void setSpacing(float d) { radius = water::radiusOfSpacing(d); }
  float h() const { return smoothing * spacing(); }

  static constexpr water::Packing kPacking = water::Packing::Cubic;  // the rest lattice (rest_lattice.h)
};

void visit(ParamVisitor& v, Params& p);

}  // namespace tidepool::fluid
