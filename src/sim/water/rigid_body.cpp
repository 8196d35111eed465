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
  const glm::dvec3 axis(o.hingeAxis);
  if (glm::length(axis) > 0.0) m_hinge = Hinge{glm::dvec3(o.centre) + glm::dvec3(o.hingeAt), glm::normalize(axis)};
}

void RigidBody::setMass(const MassProperties& mass) {
  const glm::dmat3 r = rotation();
  const glm::dvec3 shift = r * (mass.centre - m_mass.centre);  // the new centre of mass from the old
  const glm::dvec3 velocity = velocityAt(m_state.position + shift), omega = this->omega();
  m_state.position += shift;
  m_mass = mass;
  if (m_hinge) {
    setSpin(glm::dot(m_hinge->axis, omega));
    return;
  }
  m_state.momentum = mass.mass * velocity;
  m_state.angularMomentum = r * mass.inertia * glm::transpose(r) * omega;
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
  p.centre = glm::vec3(origin());
  p.velocity = glm::vec3(velocityAt(glm::dvec3(p.centre)));  // of the own frame's origin, as the contacts read it
  p.omega = glm::vec3(omega());
  return p;
}

double RigidBody::hingeInertia() const {
  const glm::dvec3 a = m_hinge->axis, r = m_state.position - m_hinge->pivot;
  const glm::dvec3 across = r - glm::dot(r, a) * a;
  const glm::dmat3 rot = rotation();
  return glm::dot(a, rot * m_mass.inertia * glm::transpose(rot) * a) + m_mass.mass * glm::dot(across, across);
}

void RigidBody::setSpin(double w) {
  const glm::dvec3 omega = w * m_hinge->axis;
  const glm::dmat3 rot = rotation();
  m_state.momentum = m_mass.mass * glm::cross(omega, m_state.position - m_hinge->pivot);
  m_state.angularMomentum = rot * m_mass.inertia * glm::transpose(rot) * omega;
}

void RigidBody::applyImpulse(glm::dvec3 impulse, glm::dvec3 at) {
  if (m_hinge) {
    const glm::dvec3 a = m_hinge->axis;
    setSpin(glm::dot(a, omega()) + glm::dot(a, glm::cross(at - m_hinge->pivot, impulse)) / hingeInertia());
    return;
  }
  m_state.momentum += impulse;
  m_state.angularMomentum += glm::cross(at - m_state.position, impulse);
}

double RigidBody::inverseMassAt(glm::dvec3 at, glm::dvec3 n) const {
  if (m_hinge) {
    const double arm = glm::dot(m_hinge->axis, glm::cross(at - m_hinge->pivot, n));
    return arm * arm / hingeInertia();
  }
  const glm::dvec3 rn = glm::cross(at - m_state.position, n);
  return 1.0 / m_mass.mass + glm::dot(rn, inverseInertiaWorld() * rn);
}

glm::dmat3 RigidBody::inverseMassMatrixAt(glm::dvec3 at) const {
  if (m_hinge) {
    const glm::dvec3 u = glm::cross(m_hinge->axis, at - m_hinge->pivot);  // the point's velocity per rad/s
    return glm::outerProduct(u, u) / hingeInertia();
  }
  const glm::dvec3 r = at - m_state.position;
  const glm::dmat3 cross(0.0, r.z, -r.y, -r.z, 0.0, r.x, r.y, -r.x, 0.0);  // cross * v = r × v
  return glm::dmat3(1.0 / m_mass.mass) - cross * inverseInertiaWorld() * cross;
}

void RigidBody::accelerate(double dt, glm::dvec3 gravity) {
  const glm::dvec3 force = m_state.force + m_mass.mass * gravity;
  if (m_hinge) {
    const glm::dvec3 a = m_hinge->axis;
    const glm::dvec3 torque = m_state.torque + glm::cross(m_state.position - m_hinge->pivot, force);
    setSpin(glm::dot(a, omega()) + dt * glm::dot(a, torque) / hingeInertia());
    return;
  }
  m_state.momentum += dt * force;
  m_state.angularMomentum += dt * m_state.torque;
}

void RigidBody::move(double dt) {
  if (m_hinge) {
    const double w = glm::dot(m_hinge->axis, omega());
    const glm::dquat turn = glm::angleAxis(w * dt, m_hinge->axis);
    m_state.position = m_hinge->pivot + turn * (m_state.position - m_hinge->pivot);
    m_state.orientation = glm::normalize(turn * m_state.orientation);
    setSpin(w);
    return;
  }
  m_state.position += dt * velocity();
  const glm::dvec3 w = omega();
  const glm::dquat spin(0.0, w.x, w.y, w.z);
  m_state.orientation = glm::normalize(m_state.orientation + (0.5 * dt) * (spin * m_state.orientation));
}

}  // namespace tidepool::water
