#include "sim/balls/measure/balls_measure.h"

#include <cmath>

#include "sim/balls/balls.h"
#include "sim/measure/bisect.h"

namespace tidepool::balls {
namespace {

Params oneBall(Integrator integrator) {
  Params p;
  p.fill = water::Fill::None;
  p.radius = 0.01f;
  p.domainMin = glm::vec3(0.0f);
  p.domainMax = glm::vec3(1.0f);
  p.contact = Contact::SpringDashpot;
  p.integrator = integrator;
  p.substeps = 1;
  p.contactTime = 0.01f;
  return p;
}

}  // namespace

Bounce measureBounce(gl::ShaderLibrary& shaders, Integrator integrator, float e, float stepsPerContact) {
  Params p = oneBall(integrator);
  p.gravity = glm::vec3(0.0f);
  p.restitution = e;
  p.dt = p.contactTime / stepsPerContact;
  Balls b(shaders, p);
  b.upload({glm::vec4(0.5f, 0.5f, p.radius + 0.01f, 1.0f)}, {glm::vec4(0.0f, 0.0f, -1.0f, 0.0f)});
  Bounce result;
  for (int i = 0; i < int(20 * stepsPerContact) + 100; ++i) {
    b.stepOnce();
    const glm::vec4 x = b.downloadPositions()[0];
    if (x.z < p.radius)
      ++result.contactSteps;
    else if (result.contactSteps > 0) {
      result.restitution = b.downloadVelocities()[0].z;  // v_in = 1 m/s
      break;
    }
  }
  return result;
}

double contactAmplitudeGrowth(gl::ShaderLibrary& shaders, Integrator integrator, double dtOverTc, int periods) {
  Params p = oneBall(integrator);
  p.restitution = 1.0f;
  p.dt = float(dtOverTc * p.contactTime);
  const double equilibrium = 9.81 / springPerMass(p);  // wall: m_eff = m
  Balls b(shaders, p);
  b.upload({glm::vec4(0.5f, 0.5f, float(p.radius - 2 * equilibrium), 1.0f)}, {glm::vec4(0.0f)});
  const int steps = int(std::ceil(periods * 2.0 / dtOverTc));  // a period is 2 t_c
  double worst = 0;
  for (int i = 0; i < steps; ++i) {
    b.stepOnce();
    const double z = b.downloadPositions()[0].z;
    if (!std::isfinite(z)) return INFINITY;
    worst = std::max(worst, std::abs((p.radius - z) - equilibrium) / equilibrium);
    if (worst > 10) break;  // clearly unstable
  }
  return worst;
}

double contactGrowthRatio(gl::ShaderLibrary& shaders, Integrator integrator, double dtOverTc, int periods) {
  // A small oscillation (0.2 x the equilibrium overlap) so that even the amplitude distortion of
  // symplectic Euler near its limit, 1/sqrt(1 − (ω0·dt/2)²), keeps the ball in contact.
  Params p = oneBall(integrator);
  p.restitution = 1.0f;
  p.dt = float(dtOverTc * p.contactTime);
  const double equilibrium = 9.81 / springPerMass(p);
  Balls b(shaders, p);
  b.upload({glm::vec4(0.5f, 0.5f, float(p.radius - 1.2 * equilibrium), 1.0f)}, {glm::vec4(0.0f)});
  const int perPeriod = int(std::ceil(2.0 / dtOverTc));  // a period is 2 t_c
  const int steps = periods * perPeriod;
  double first = 0, late = 0;
  for (int i = 0; i < steps; ++i) {
    b.stepOnce();
    const double z = b.downloadPositions()[0].z;
    if (!std::isfinite(z)) return INFINITY;
    const double deviation = std::abs((p.radius - z) - equilibrium);
    if (i < perPeriod) first = std::max(first, deviation);
    if (i >= steps - perPeriod) late = std::max(late, deviation);
    if (deviation > 50 * equilibrium) return INFINITY;  // clearly unstable
  }
  return late / std::max(first, 1e-30);
}

double stableStepLimit(gl::ShaderLibrary& shaders, Integrator integrator, double tolerance) {
  auto stable = [&](double dtOverTc) { return contactGrowthRatio(shaders, integrator, dtOverTc, 12) < 1.5; };
  return largestStable(0.05, 2.0, tolerance, stable);
}

ColumnScales columnScales(const water::Setup& p) {
  const bool block = p.fill == water::Fill::Block;
  const glm::vec3 lo = block ? glm::max(p.fillMin, p.domainMin) : p.domainMin;
  const glm::vec3 hi = block ? glm::min(p.fillMax, p.domainMax) : p.domainMax;
  return {hi.x - lo.x, hi.z - lo.z};
}

double frontOverWidth(const water::Setup& p, const Stats& s, float radius) {
  return (s.front - p.domainMin.x + radius) / columnScales(p).width;
}

}  // namespace tidepool::balls
