// What a renderer, an exporter and a probe read of a particle-water model, balls or fluid alike:
// the particles' buffers, their size, the obstacles, the walls and the domain's turn, and the
// water setup. The water view (render/balls_view.h) draws either model through this, so the two
// look the same.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <glm/glm.hpp>
#include <vector>

#include "gl/buffer.h"
#include "sim/divergence.h"
#include "sim/water/obstacles.h"
#include "sim/water/setup.h"

namespace tidepool::grid {
class UniformGrid;
}

namespace tidepool::water {

// What the water exerted on a boundary during the last step: the force (N) and, on an obstacle,
// the torque about its centre (N·m).
struct Load {
  glm::dvec3 force{0.0}, torque{0.0};
  static Load unmeasured() { return {glm::dvec3(NAN), glm::dvec3(NAN)}; }
};
constexpr std::size_t kWalls = 6;  // −x, +x, −y, +y, −z, +z
struct Loads {
  std::array<Load, kWalls> walls;  // a wall's force is along its normal
  std::vector<Load> obstacles;     // one per obstacle
  void unmeasuredWalls() {         // NaN forces (a wall has no torque)
    for (Load& w : walls) w.force = glm::dvec3(NAN);
  }
  static Loads unmeasured(std::size_t obstacles) {  // NaN throughout
    Loads none;
    none.unmeasuredWalls();
    none.obstacles.assign(obstacles, Load::unmeasured());
    return none;
  }
};

// The uniforms of a water model's health.comp (common/health.glsl, water/health.glsl).
struct HealthUniforms {
  sim::HealthUniforms window;
  glm::vec3 wallMin{0.0f}, wallMax{0.0f};  // m: particles outside are flagged
  static constexpr auto fields() {
    using U = HealthUniforms;
    return std::tuple{gl::field(&U::window), gl::field("uWallMin", &U::wallMin), gl::field("uWallMax", &U::wallMax)};
  }
};

class ParticleWater {
 public:
  virtual ~ParticleWater() = default;
  virtual const gl::Buffer& positions() const = 0;   // vec4 (m, w = 1), count() of them
  virtual const gl::Buffer& velocities() const = 0;  // vec4 (m/s, w = foam)
  virtual std::size_t count() const = 0;
  virtual float radius() const = 0;                // m: r of setup.h's particle size, as the model runs it
  virtual Packing packing() const = 0;             // how its particles pack at rest
  virtual const Obstacles& obstacles() const = 0;  // as placed at the last step
  virtual const Setup& water() const = 0;          // domain, fill, walls, tap, obstacles, engine
  virtual glm::vec3 wallMin() const = 0;           // current walls (the piston moves one)
  virtual glm::vec3 wallMax() const = 0;
  virtual float domainRotation() const = 0;  // radians about x
  // The neighbour grid in the particles' frame, its counts as of the last sort (debug views);
  // null before the first step or for a model without one.
  virtual const grid::UniformGrid* neighbourGrid() const { return nullptr; }
  // The water's pressure (Pa) at each point, as of the last step (sim/water/probes.h; NaN before
  // the first step). Throws Error where the model has no pressure field.
  virtual std::vector<double> pressures(const std::vector<glm::vec3>& points) = 0;
  // The loads of the last step on the walls and the obstacles, measured while the setup lists a
  // force probe (the walls' while one is on a wall; NaN where not measured or before the first
  // such step). Throws Error where the model has none.
  virtual Loads loads() = 0;
};

}  // namespace tidepool::water
