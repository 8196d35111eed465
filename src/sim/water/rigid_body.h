// A dynamic obstacle as a rigid body: six degrees of freedom (the centre of mass, the orientation
// as a unit quaternion, linear and angular momentum), its mass, centre of mass and inertia
// computed from its particles, and what the water did to it in the last step. Integrated with the
// water's steps (semi-implicit Euler, in double):
//   P += dt (F + m g),  L += dt τ         the water's load of the last step, and gravity
//   contacts (body_contacts.h)           impulses that stop it entering a wall or another body
//   x += dt P / m,  q += dt/2 (0, ω) q   ω = R I⁻¹ Rᵀ L, then q normalised
// A hinged body keeps one degree of freedom, its spin w about the hinge's axis a through the
// pivot p: w += dt a·τ_p / I_p, with τ_p the torque about p (gravity's too) and I_p the inertia
// about the axis; then it turns by w dt about the axis, exactly. P and L stay those of that spin.
// The water's force and torque come from the step before (explicit coupling, as in Akinci et al.
// 2012, "Versatile rigid-fluid coupling for incompressible SPH").
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <optional>
#include <vector>

#include "sim/water/obstacle_pose.h"

namespace tidepool::water {

struct MassProperties {
  double mass = 0;                 // kg
  glm::dvec3 centre{0.0};          // centre of mass in the own frame, m
  glm::dmat3 inertia{1.0};         // about the centre of mass, own frame, kg·m²
  glm::dmat3 inverseInertia{1.0};  // its inverse, 1/(kg·m²)
};
// Mass = density × volume; the centre and the inertia as of equal masses on the particles (own
// frame, as built), plus each particle's own share as a cube of the lattice's volume per particle.
MassProperties massProperties(const std::vector<glm::vec4>& particles, double volume, double density);

// The state a step changes: what checkpoints and the divergence watch keep, kBodyDoubles doubles.
struct BodyState {
  glm::dvec3 position{0.0};                    // the centre of mass, world, m
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  // own frame -> world
  glm::dvec3 momentum{0.0};                    // kg·m/s
  glm::dvec3 angularMomentum{0.0};             // about the centre of mass, world, kg·m²/s
  glm::dvec3 force{0.0}, torque{0.0};          // the water's in the last step, N and N·m about the centre of mass
  double pad = 0;
};
constexpr std::size_t kBodyDoubles = sizeof(BodyState) / sizeof(double);
static_assert(sizeof(BodyState) == 20 * sizeof(double), "BodyState is a plain record of doubles");

// An axis fixed in the world that a body only turns about.
struct Hinge {
  glm::dvec3 pivot{0.0};  // a point of the axis, world, m
  glm::dvec3 axis{0.0};   // unit
};

class RigidBody {
 public:
  // At rest, where the obstacle's centre and orientation put it, on its hinge if it has one.
  RigidBody(const MassProperties& mass, const ObstacleParams& o);

  const MassProperties& mass() const { return m_mass; }
  void setMass(const MassProperties& mass);  // new mass properties, the same motion about the new centre
  BodyState& state() { return m_state; }
  const BodyState& state() const { return m_state; }

  glm::dmat3 rotation() const { return glm::mat3_cast(m_state.orientation); }
  glm::dvec3 velocity() const { return m_state.momentum / m_mass.mass; }  // of the centre of mass
  glm::dvec3 omega() const;                                               // world, rad/s
  glm::dmat3 inverseInertiaWorld() const;                                 // R I⁻¹ Rᵀ
  glm::dvec3 velocityAt(glm::dvec3 world) const { return velocity() + glm::cross(omega(), world - m_state.position); }
  ObstaclePose pose() const;  // for placing its particles: the own frame's origin
  glm::dvec3 origin() const { return m_state.position - rotation() * m_mass.centre; }  // pose().centre, in double
  const std::optional<Hinge>& hinge() const { return m_hinge; }

  void applyImpulse(glm::dvec3 impulse, glm::dvec3 at);  // at a world point
  // 1 / (the impulse along the unit n at a world point that changes the velocity there along n by one unit).
  double inverseMassAt(glm::dvec3 at, glm::dvec3 n) const;
  // The same for any impulse J: the velocity there changes by K J (K singular for a hinged body).
  glm::dmat3 inverseMassMatrixAt(glm::dvec3 at) const;
  // Gravity and the water's last load, over dt.
  void accelerate(double dt, glm::dvec3 gravity);
  void move(double dt);  // the pose, with the momenta as they now are

 private:
  double hingeInertia() const;  // about the hinge's axis, kg·m²
  void setSpin(double w);       // P and L of a hinged body turning at w rad/s

  MassProperties m_mass;
  BodyState m_state;
  std::optional<Hinge> m_hinge;
};

}  // namespace tidepool::water
