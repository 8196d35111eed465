// The dynamic obstacles of a particle-water model, coupled to its water (the balls and the fluid
// alike): the bodies (bodies.h), the loads the model measures on them (boundary_loads.h), and
// their states as one of the model's state buffers (checkpoints and the divergence watch).
//
// A step asks for the water's loads on the bodies at its end (requestLoads) and the next step
// reads them (in move()) after it has queued the passes that do not read the obstacles, so that the
// GPU has work while the CPU waits; move() then takes the bodies to where the step's forces act
// (from the state buffer after a restore or a load). settle() writes their states, with any loads still on
// the way, into that buffer.
#pragma once

#include <optional>
#include <vector>

#include "gl/buffer.h"
#include "sim/model_state.h"
#include "sim/water/bodies.h"
#include "sim/water/boundary_loads.h"

namespace tidepool::water {

class BodyCoupling {
 public:
  // The model's loads and obstacles (declared before this in the model: they outlive it).
  BodyCoupling(BoundaryLoads& loads, const Obstacles& obstacles) : m_loads(loads), m_obstacles(obstacles) {}

  Bodies& bodies() { return m_bodies; }  // the window's mouse pulls them (Bodies::grab)
  const Bodies& bodies() const { return m_bodies; }
  bool any() const { return m_bodies.any(); }

  // Bodies anew for the obstacles as built (reset), at rest where the parameters put them.
  void reset(const std::vector<ObstacleParams>& params);
  void sync(const std::vector<ObstacleParams>& params) { m_bodies.sync(params, m_obstacles); }
  // The step's loads are summed (`measured`; else none reached the bodies): on their way back.
  void requestLoads(bool measured);
  // One step of dt (Bodies::advance): the last step's loads (times `scale`, boundary_loads.h),
  // gravity, and contacts with the walls and the kinematic obstacles at `poses`, where this
  // step's forces act.
  void move(double dt, double scale, glm::dvec3 gravity, const Walls& walls, const std::vector<ObstaclePose>& poses);
  // The bodies' states in their buffer, for a checkpoint or the watch (receiving any loads on the way).
  void settle(double scale);
  // "bodies": the state buffer, while there are bodies (settled first).
  std::optional<sim::StateBuffer> stateBuffer(double scale);
  // The state buffer was loaded or restored: the bodies read it at the next move(); no loads pending.
  void restored();

 private:
  void receiveLoads(double scale);

  BoundaryLoads& m_loads;
  const Obstacles& m_obstacles;
  Bodies m_bodies;
  gl::Buffer m_state;       // BodyState per obstacle
  bool m_restored = false;  // m_state was loaded or restored: m_bodies reads it at the next move()
  bool m_pending = false;   // the last step's loads are on their way back (requestLoads)
};

}  // namespace tidepool::water
