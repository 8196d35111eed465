// The dynamic obstacles of the water (`"dynamic": true`) as rigid bodies (rigid_body.h). Each step:
//   poses()     where every obstacle is: a body from its state, the others from the time
//   ...         the model's step, which measures the water's loads on them (particle_water.h)
//   setLoads()  those loads, the torque taken about each body's centre of mass
//   advance()   gravity and the loads, then contacts with the walls, the other bodies and the
//               kinematic obstacles
//               (body_contacts.h), then the move to the next step's pose
// The states are plain records of doubles (BodyState), one per obstacle, that the model keeps in
// its state buffers, so checkpoints and the divergence watch keep them with the particles.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "sim/water/body_contacts.h"
#include "sim/water/obstacles.h"
#include "sim/water/particle_water.h"
#include "sim/water/rigid_body.h"

namespace tidepool::water {

class Bodies {
 public:
  // After the obstacles were built or updated: a body for each dynamic obstacle. A new one starts
  // at rest at its centre and orientation; one kept keeps its motion, unless its centre or
  // orientation or hinge was edited (then it starts again there, at rest) or its shape or density
  // (its mass properties are made anew).
  void sync(const std::vector<ObstacleParams>& params, const Obstacles& obstacles);
  bool any() const;
  bool dynamic(std::size_t k) const { return k < m_bodies.size() && m_bodies[k].has_value(); }
  const RigidBody& body(std::size_t k) const { return *m_bodies[k]; }

  // Every obstacle's pose for a step ending at `time`.
  std::vector<ObstaclePose> poses(const std::vector<ObstacleParams>& params, double time) const;
  // The water's loads of the step just taken (forces; torques about each obstacle's own origin).
  void setLoads(const Loads& loads, const Obstacles& obstacles);
  // One step of dt: momenta from gravity and the last loads, contact impulses (with the walls, each
  // other and the kinematic obstacles at `poses`, the step's end), then the poses.
  void advance(double dt, glm::dvec3 gravity, const Walls& walls, const Obstacles& obstacles,
               const std::vector<ObstaclePose>& poses);

  std::vector<BodyState> states() const;  // one per obstacle (zero for a kinematic one)
  void setStates(const std::vector<BodyState>& states);

  // The window's mouse: a point fixed in one body pulled toward a target. Each step, before the
  // loads and contacts, an impulse at the point (solved with the body's 3 × 3 inverse mass there)
  // gives it the velocity that would close the gap in kPullTime; at most kPullMost times the
  // impulse of its weight (or of 9.81 m/s² without gravity).
  static constexpr double kPullTime = 0.1, kPullMost = 20.0;
  struct Grab {
    std::size_t obstacle = 0;
    glm::dvec3 anchor{0.0};  // own frame, from the centre of mass, m
    glm::dvec3 target{0.0};  // world, m
  };
  void grab(std::optional<Grab> g) { m_grab = g; }
  // The dynamic obstacle whose particles (spheres of radius r) a ray from `origin` along the unit
  // `direction` meets first: its index and the distance along the ray.
  std::optional<std::pair<std::size_t, double>> pick(const Obstacles& obstacles, glm::dvec3 origin,
                                                     glm::dvec3 direction) const;
  glm::dvec3 anchorAt(std::size_t k, glm::dvec3 world) const;  // a world point in body k's frame, as Grab::anchor

 private:
  void pull(double dt, glm::dvec3 gravity);

  struct Tracked {  // what a body was made from, to see edits
    unsigned id = 0;
    glm::vec3 centre{0.0f}, orientation{0.0f}, hingeAxis{0.0f}, hingeAt{0.0f};
    float density = 0;
  };
  std::vector<std::optional<RigidBody>> m_bodies;
  std::vector<Tracked> m_made;
  std::optional<Grab> m_grab;
};

}  // namespace tidepool::water
