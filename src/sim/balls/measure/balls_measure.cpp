#include "sim/balls/measure/balls_measure.h"

#include <cmath>

#include "sim/balls/balls.h"

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
