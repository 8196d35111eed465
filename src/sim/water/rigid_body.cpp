#include "sim/water/rigid_body.h"

#include <cmath>

namespace tidepool::water {

MassProperties massProperties(const std::vector<glm::vec4>& particles, double volume, double density) {
  MassProperties m;
  m.mass = density * volume;
  if (particles.empty() || !(m.mass > 0.0)) return m;
  const double n = double(particles.size()), each = m.mass / n;
  glm::dvec3 sum(0.0);
  for (const glm::vec4& q : particles) sum += glm::dvec3(q);
  m.centre = sum / n;
  glm::dmat3 inertia(0.0);
  for (const glm::vec4& q : particles) {
    const glm::dvec3 r = glm::dvec3(q) - m.centre;
    inertia += each * (glm::dot(r, r) * glm::dmat3(1.0) - glm::outerProduct(r, r));
  }
  // Each particle a cube of side a = (volume / n)^(1/3): a²/6 of its mass about each axis.
  const double a2 = std::pow(volume / n, 2.0 / 3.0);
  inertia += m.mass * a2 / 6.0 * glm::dmat3(1.0);
  m.inertia = inertia;
  m.inverseInertia = glm::inverse(inertia);
  return m;
}

RigidBody::RigidBody(const MassProperties& mass, const ObstacleParams& o) : m_mass(mass) {
  const glm::dmat3 r(orientationMatrix(o.orientation));
  m_state.orientation = glm::normalize(glm::quat_cast(r));
  m_state.position = glm::dvec3(o.centre) + r * mass.centre;
}

glm::dmat3 RigidBody::inverseInertiaWorld() const {
  const glm::dmat3 r = rotation();
  return r * m_mass.inverseInertia * glm::transpose(r);
}

glm::dvec3 RigidBody::omega() const { return inverseInertiaWorld() * m_state.angularMomentum; }

ObstaclePose RigidBody::pose() const {
  const glm::dmat3 r = rotation();
  ObstaclePose p;
  p.rotation = glm::mat3(r);
  p.centre = glm::vec3(m_state.position - r * m_mass.centre);
  p.velocity = glm::vec3(velocityAt(glm::dvec3(p.centre)));  // of the own frame's origin, as the contacts read it
  p.omega = glm::vec3(omega());
  return p;
}

void RigidBody::applyImpulse(glm::dvec3 impulse, glm::dvec3 at) {
  m_state.momentum += impulse;
  m_state.angularMomentum += glm::cross(at - m_state.position, impulse);
}

void RigidBody::accelerate(double dt, glm::dvec3 gravity) {
  m_state.momentum += dt * (m_state.force + m_mass.mass * gravity);
  m_state.angularMomentum += dt * m_state.torque;
}

void RigidBody::move(double dt) {
  m_state.position += dt * velocity();
  const glm::dvec3 w = omega();
  const glm::dquat spin(0.0, w.x, w.y, w.z);
  m_state.orientation = glm::normalize(m_state.orientation + (0.5 * dt) * (spin * m_state.orientation));
}

}  // namespace tidepool::water
