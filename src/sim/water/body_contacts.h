// Rigid bodies against the walls, each other and the fixed or moving (kinematic) obstacles,
// through their particles: a particle of radius r touches a wall at r and another body's or
// obstacle's particle at 2r. Each touching (or, within `margin`,
// nearly touching) pair is a contact, and sequential impulses (Catto, "Iterative Dynamics with
// Temporal Coherence", GDC 2005) find the contact impulses, in a fixed order:
//   normal    λ ≥ 0, so that v_n ≥ −gap/dt (a gap closes no faster than it can in one step)
//             or v_n ≥ β·overlap/dt (an overlap is pushed out over a few steps)
//   friction  Coulomb: the tangential impulse at most μ λ, against the sliding velocity
// Walls and kinematic obstacles do not move in response (a piston wall or a turning obstacle moves
// at its own velocity).
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "sim/water/rigid_body.h"
#include "sim/water/water_frame.h"

namespace tidepool::water {

struct ContactBody {
  RigidBody* body = nullptr;                          // null: a kinematic obstacle at `pose`
  const std::vector<glm::vec4>* particles = nullptr;  // own frame, as built
  double reach = 0;                                   // largest |particle| + r about the own frame's origin, m
  ObstaclePose pose;                                  // a kinematic obstacle's, at the step's end
};

struct BodyContact {
  int a = 0, b = -1;       // the bodies' indices in the list; b = -1: a wall
  glm::dvec3 point{0.0};   // world, m
  glm::dvec3 normal{0.0};  // pushes a away from b (or the wall)
  double gap = 0;          // m beyond touching; negative: overlapping
  glm::dvec3 wallVelocity{0.0};
};

struct ContactSettings {
  double radius = 0;       // r, m
  double margin = 0;       // pairs this far apart are contacts already, m
  double friction = 0.5;   // μ
  double baumgarte = 0.2;  // β: the fraction of an overlap pushed out per step
  int iterations = 10;     // sweeps over the contacts
};

// The contacts of the bodies at their present poses, wall contacts first, in a fixed order.
std::vector<BodyContact> findContacts(const std::vector<ContactBody>& bodies, const Walls& walls,
                                      const ContactSettings& s);
// Applies the contact impulses to the bodies' momenta for a step of dt.
void resolveContacts(const std::vector<ContactBody>& bodies, const std::vector<BodyContact>& contacts, double dt,
                     const ContactSettings& s);
// One step of dt for all the bodies (rigid_body.h): gravity and each one's load, then the contacts
// (the margin: half a radius, or what the fastest point travels in two steps), then the move. The
// kinematic obstacles in the list only take part in the contacts.
void stepBodies(const std::vector<ContactBody>& bodies, double dt, glm::dvec3 gravity, const Walls& walls,
                double radius);

}  // namespace tidepool::water
