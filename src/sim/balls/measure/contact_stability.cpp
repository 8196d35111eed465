#include "sim/balls/measure/contact_stability.h"

#include <cmath>
#include <numbers>
#include <string>

#include "base/error.h"
#include "sim/balls/balls.h"
#include "sim/measure/bisect.h"

namespace tidepool::balls {
namespace {

constexpr float kRadius = 0.01f;
constexpr double kEquilibrium = 0.1 * kRadius;  // overlap at rest, m
constexpr double kPush = 0.02 * kEquilibrium;   // start this much further in, m
const glm::vec3 kCentre{0.1f};                  // the fixed particle's obstacle, in a 0.2 m box

// Per-step stiffness per unit of overlap (ω² = stiffness) of a ball on a fixed body, 1/s².
double stiffness(const Params& p) {
  switch (p.contact) {
    case Contact::Penalty: return p.penaltyFactor / p.dt;
    case Contact::CudaSample: return p.cudaSpring / p.dt;
    case Contact::SpringDashpot: break;
  }
  return springPerMass(p);
}

// The resting contact's box and law, without its step, gravity and fixed body.
Params restingBase(Contact law, Integrator integrator) {
  Params p;
  p.fill = water::Fill::None;
  p.radius = kRadius;
  p.domainMin = glm::vec3(0.0f);
  p.domainMax = glm::vec3(2.0f * kCentre);
  p.contact = law;
  p.integrator = integrator;
  p.substeps = 1;
  p.damping = 0.0f;
  p.restitution = 1.0f;
  p.contactTime = 0.01f;
  return p;
}

// Where the one fixed particle of a resting-contact model is (world, m).
glm::vec3 fixedParticle(const Balls& b) {
  if (b.obstacleCount() != 1)
    throw Error("resting contact: the fixed body has " + std::to_string(b.obstacleCount()) + " particles, not 1");
  return kCentre + glm::vec3(b.obstacles().body(0).particles[0]);
}

}  // namespace

double restingStep(Contact law, double omegaDt) {
  const Params p = restingBase(law, Integrator::SymplecticEuler);
  switch (law) {
    case Contact::Penalty: return omegaDt * omegaDt / p.penaltyFactor;
    case Contact::CudaSample: return omegaDt * omegaDt / p.cudaSpring;
    case Contact::SpringDashpot: break;
  }
  return omegaDt / std::sqrt(double(springPerMass(p)));  // ω = π/t_c at e = 1
}

double restingVelocityFactor(Contact law) { return law == Contact::CudaSample ? 1.0 - Params().cudaDamping : 1.0; }

Params restingContact(Contact law, Integrator integrator, double omegaDt) {
  Params p = restingBase(law, integrator);
  p.dt = float(restingStep(law, omegaDt));
  p.gravity = glm::vec3(0.0f, 0.0f, float(-kEquilibrium * stiffness(p)));
  // A sphere of radius r holds exactly one lattice particle, near its centre.
  water::ObstacleParams body;
  body.shape = water::Shape::Sphere;
  body.centre = kCentre;
  body.size = glm::vec3(kRadius);
  p.obstacles = {body};
  return p;
}

RestingRun restingRun(gl::ShaderLibrary& shaders, Contact law, Integrator integrator, double omegaDt, int steps) {
  const Params p = restingContact(law, integrator, omegaDt);
  Balls b(shaders, p);
  const glm::vec3 fixed = fixedParticle(b);
  const double rest = 2.0 * p.radius - kEquilibrium;  // centre distance at equilibrium
  b.upload({glm::vec4(fixed.x, fixed.y, float(fixed.z + rest - kPush), 1.0f)}, {glm::vec4(0.0f)});
  const int window = steps / 4;
  double first = 0, late = 0, largest = 0;
  for (int i = 0; i < steps; ++i) {
    b.stepOnce();
    const double z = b.downloadPositions()[0].z;
    const double y = std::abs(z - fixed.z - rest);
    if (!std::isfinite(y) || y > kRestingBlowUp * kPush) return {INFINITY, INFINITY};
    largest = std::max(largest, y);
    if (i < window) first = std::max(first, y);
    if (i >= steps - window) late = std::max(late, y);
  }
  return {late / std::max(first, 1e-30), largest / kPush};
}

double restingStableLimit(gl::ShaderLibrary& shaders, Contact law, Integrator integrator, double tolerance, int steps) {
  return largestStable(0.05, 4.0, tolerance, [&](double h) {
    return restingRun(shaders, law, integrator, h, steps).growth < kRestingGrowthBound;
  });
}

namespace {

// Largest overlap, fraction of r, of a ball released at rest just touching the fixed particle,
// over one period of its contact oscillation (the first overshoot comes within half of one).
double releaseOverlap(gl::ShaderLibrary& shaders, Contact law, double dt) {
  Params p = restingContact(law, Integrator::SymplecticEuler, 1.0);
  p.dt = float(dt);
  p.gravity = glm::vec3(0.0f, 0.0f, -9.81f);
  Balls b(shaders, p);
  const glm::vec3 fixed = fixedParticle(b);
  b.upload({glm::vec4(fixed.x, fixed.y, fixed.z + 2.0f * p.radius, 1.0f)}, {glm::vec4(0.0f)});
  const int steps = int(std::ceil(2.0 * std::numbers::pi / std::sqrt(stiffness(p) * dt * dt)));
  double worst = 0;
  for (int i = 0; i < steps; ++i) {
    b.stepOnce();
    const double z = b.downloadPositions()[0].z;
    if (!std::isfinite(z)) return INFINITY;
    worst = std::max(worst, (2.0 * p.radius - (z - fixed.z)) / p.radius);
    if (worst > 1.0) break;
  }
  return worst;
}

}  // namespace

double overlapStepLimit(gl::ShaderLibrary& shaders, Contact law, double tolerance) {
  return largestStable(1e-5, 1e-2, tolerance, [&](double dt) { return releaseOverlap(shaders, law, dt) < 1.0; });
}

double overlapStepTheory(Contact law) {
  const Params p;
  const double g = 9.81, r = kRadius;
  if (law == Contact::Penalty) return p.penaltyFactor * r / (2.0 * g);
  if (law != Contact::CudaSample) return 0.0;  // the spring's overlap does not depend on dt
  const double c = p.cudaDamping, s = p.cudaSpring;
  const auto overlap = [&](double dt) {  // largest overlap over r at dt
    const double zeta = c / (2.0 * std::sqrt(s * dt));
    const double overshoot = zeta < 1.0 ? std::exp(-std::numbers::pi * zeta / std::sqrt(1.0 - zeta * zeta)) : 0.0;
    return g * dt / s * (1.0 + overshoot) / r;
  };
  return bisectLimit(1e-5, 1e-2, 1e-6, [&](double dt) { return overlap(dt) < 1.0; });
}

double restingTheoryLimit(Contact law, Integrator integrator) {
  const double f = restingVelocityFactor(law);
  return integrator == Integrator::ExplicitEuler ? std::sqrt(1.0 - f) : std::sqrt(2.0 * (1.0 + f));
}

}  // namespace tidepool::balls
