#include "sim/balls/balls_params.h"

#include <cmath>
#include "sim/water/probes.h"

namespace tidepool::balls {

void visit(ParamVisitor& v, Params& p) {
  if (v.beginGroup({"particles", "Particles", "count, size and initial state (re-creates the particles)"})) {
    v.real({"radius", "Radius", "r, m"}, p.radius, 1e-4f, 0.5f);
    water::visitFill(v, p);
    v.integer({"lattice_count", "Lattice count", "particles"}, p.latticeCount, 1, 1 << 30);
    v.flag({"lattice_scaling", "Lattice scaling", "r = 1/G and gravity x 64/G as the CUDA sample"}, p.latticeScaling);
    v.endGroup();
  }
  if (v.beginGroup({"engine", "Engine", "time step, contact law, integrator"})) {
    v.choice({"contact", "Contact", "penalty (the seed's), spring-dashpot (linear DEM) or cuda-sample"}, p.contact,
             kContactNames);
    v.choice({"integrator", "Integrator", "explicit Euler, symplectic Euler or velocity Verlet"}, p.integrator,
             kIntegratorNames);
    water::visitEngine(v, p, 1.0f);
    v.flag({"deterministic", "Deterministic", "bit-identical runs: the grid orders each cell's balls by index"},
           p.deterministic);
    v.real({"contact_time", "Contact time", "t_c of spring-dashpot, s"}, p.contactTime, 1e-6f, 10.0f);
    v.real({"restitution", "Restitution", "e of spring-dashpot"}, p.restitution, 0.01f, 1.0f);
    v.real({"friction", "Friction", "tangential Coulomb coefficient (spring-dashpot)"}, p.friction, 0.0f, 2.0f);
    v.real({"penalty_factor", "Penalty factor", "seed: 0.96"}, p.penaltyFactor, 0.0f, 2.0f);
    v.real({"cuda_spring", "CUDA spring", "per-step velocity change per overlap"}, p.cudaSpring, 0.0f, 2.0f);
    v.real({"cuda_damping", "CUDA damping", "per step"}, p.cudaDamping, 0.0f, 1.0f);
    v.real({"cuda_shear", "CUDA shear", "per step"}, p.cudaShear, 0.0f, 1.0f);
    v.real({"cuda_boundary_damping", "CUDA wall factor", "velocity factor at walls"}, p.cudaBoundaryDamping, -1.0f,
           1.0f);
    v.real({"rest_density", "Rest density", "rho0, kg/m^3: a ball weighs rho0 times the water it stands for at rest"},
           p.restDensity, 1.0f, 1e5f);
    water::visitFoam(v, p);
    v.endGroup();
  }
  if (v.beginGroup({"walls", "Walls", "piston and domain rotation"})) {
    water::visitWalls(v, p);
    v.endGroup();
  }
  if (v.beginGroup({"tap", "Tap", "emits balls over time"})) {
    water::visitTap(v, p);
    v.endGroup();
  }
  water::visitObstacles(v, p);
  water::visitProbes(v, p.probes);
}

water::Setup resolved(const Params& p) {
  water::Setup q = p;
  if (p.fill != water::Fill::Lattice || !p.latticeScaling) return q;
  const int side = int(std::ceil(std::cbrt(double(p.latticeCount)) - 1e-9));
  int g = 1;
  while (g < side) g *= 2;
  q.radius = (p.domainMax.x - p.domainMin.x) / (2.0f * float(g));
  q.gravity = p.gravity * (64.0f / float(g));
  return q;
}

void refine(Params& p, double factor) {
  water::refine(p, factor);  // throws before changing anything
  p.contactTime = float(double(p.contactTime) / factor);
}

}  // namespace tidepool::balls
