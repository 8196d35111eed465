// Parameters of the balls model: the water (sim/water/setup.h: domain, fill, walls, tap, obstacles,
// engine step, radius r) and the balls' own physics: the contact law, the integrator, and the CUDA
// sample's lattice scaling; declared once for JSON and UI.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "base/param.h"
#include "sim/water/setup.h"

namespace tidepool::balls {

enum class Contact { Penalty, SpringDashpot, CudaSample };
constexpr std::array<const char*, 3> kContactNames = {"penalty", "spring-dashpot", "cuda-sample"};
enum class Integrator { ExplicitEuler, SymplecticEuler, VelocityVerlet };
constexpr std::array<const char*, 3> kIntegratorNames = {"explicit-euler", "symplectic-euler", "verlet"};

// The water setup is a base (not a member): balls code reads p.radius, p.dt as the water's.
struct Params : water::Setup {
  bool latticeScaling = true;  // lattice fill: r = width/(2G), gravity x 64/G (CUDA sample)
  Contact contact = Contact::SpringDashpot;
  Integrator integrator = Integrator::SymplecticEuler;
  // spring-dashpot: k and gamma from the contact duration and restitution (per unit effective mass)
  float contactTime = 0.01f;  // t_c, s
  float restitution = 0.5f;   // e
  float friction = 0.0f;      // Coulomb coefficient (tangential), 0: frictionless
  // penalty (the seed's): velocity change 0.96 * share * overlap per step; walls 2 * overlap
  float penaltyFactor = 0.96f;
  // cuda-sample: per-step velocity changes (NVIDIA CUDA "particles" sample)
  float cudaSpring = 0.5f, cudaDamping = 0.02f, cudaShear = 0.1f, cudaBoundaryDamping = -0.5f;
  // A ball's mass is ρ0 times the volume of water it stands for at rest (volumePerParticle): what
  // the loads on the walls, the obstacles and the bodies are measured with.
  float restDensity = 1000.0f;  // ρ0, kg/m³

  static constexpr water::Packing kPacking = water::Packing::Hcp;  // balls at rest (sim/water/setup.h)
};

void visit(ParamVisitor& v, Params& p);

// The water as the balls run it: the lattice fill's derived radius and gravity (CUDA sample:
// r = width/(2G), g x 64/G with G the next power of two >= ceil(N^(1/3))); other fills unchanged.
water::Setup resolved(const Params& p);

// water::refine, and the contact time ÷ f with the radius (contact stiffness of a material:
// t_c ∝ r keeps the overlap under a column of water the same fraction of r). Throws Error; `p`
// is then unchanged.
void refine(Params& p, double factor);

// Spring constant and dashpot coefficient per unit effective mass from t_c and e:
//   k = (pi^2 + ln^2 e) / t_c^2,  gamma = -2 ln e / t_c   (linear spring-dashpot, exact t_c and e)
inline float springPerMass(const Params& p) {
  const float le = std::log(std::max(p.restitution, 1e-6f));
  return (9.8696044f + le * le) / (p.contactTime * p.contactTime);
}
inline float dashpotPerMass(const Params& p) {
  return -2.0f * std::log(std::max(p.restitution, 1e-6f)) / p.contactTime;
}

}  // namespace tidepool::balls
