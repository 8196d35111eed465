// The uniforms of the balls' kernels (gl/kernel.h): one struct per kernel, built from the parts
// its includes declare. A field names its GLSL uniform once; the program is checked against the
// struct when it is built, so a misspelled or missing uniform is an error, not a silent no-op.
#pragma once

#include "gl/kernel.h"
#include "grid/grid.h"
#include "sim/water/obstacles.h"

namespace tidepool::balls {

struct WallUniforms {                    // balls/walls.glsl
  glm::vec3 min{0.0f}, max{1.0f};        // current wall positions, m
  glm::vec3 minVel{0.0f}, maxVel{0.0f};  // m/s (the piston)
  float boundaryDamping = 0;             // CUDA sample: velocity factor at a wall
  static constexpr auto fields() {
    using U = WallUniforms;
    return std::tuple{gl::field("uWallMin", &U::min), gl::field("uWallMax", &U::max),
                      gl::field("uWallMinVel", &U::minVel), gl::field("uWallMaxVel", &U::maxVel),
                      gl::field("uBoundaryDamping", &U::boundaryDamping)};
  }
};

struct ContactUniforms {  // balls/contact.glsl
  float dt = 0;           // s
  float penaltyFactor = 0;
  float springK1 = 0;   // 1/s² per unit effective mass
  float dashpotG1 = 0;  // 1/s per unit effective mass
  float friction = 0;
  float cudaSpring = 0, cudaDamping = 0, cudaShear = 0;
  static constexpr auto fields() {
    using U = ContactUniforms;
    return std::tuple{gl::field("uDt", &U::dt),
                      gl::field("uPenaltyFactor", &U::penaltyFactor),
                      gl::field("uSpringK1", &U::springK1),
                      gl::field("uDashpotG1", &U::dashpotG1),
                      gl::field("uFriction", &U::friction),
                      gl::field("uCudaSpring", &U::cudaSpring),
                      gl::field("uCudaDamping", &U::cudaDamping),
                      gl::field("uCudaShear", &U::cudaShear)};
  }
};

struct NeighbourUniforms {  // balls/neighbours.glsl
  float radius = 0;         // m
  GLuint sourceFirst = 0;   // the first ball of the inputs' window
  grid::GridUniforms grid;
  water::ObstacleUniforms obstacles;
  static constexpr auto fields() {
    using U = NeighbourUniforms;
    return std::tuple{gl::field("uRadius", &U::radius), gl::field("uSourceFirst", &U::sourceFirst), gl::field(&U::grid),
                      gl::field(&U::obstacles)};
  }
};

struct DriftUniforms {          // balls/drift.comp
  GLuint first = 0, count = 0;  // balls [first, count)
  float dt = 0, radius = 0, foamGain = 0, foamDecay = 1;
  WallUniforms walls;
  static constexpr auto fields() {
    using U = DriftUniforms;
    return std::tuple{gl::field("uFirst", &U::first),
                      gl::field("uCount", &U::count),
                      gl::field("uDt", &U::dt),
                      gl::field("uRadius", &U::radius),
                      gl::field("uFoamGain", &U::foamGain),
                      gl::field("uFoamDecay", &U::foamDecay),
                      gl::field(&U::walls)};
  }
};

struct CollideUniforms {        // balls/collide.comp
  GLuint first = 0, count = 0;  // balls [first, count)
  glm::vec3 gravity{0.0f};      // m/s², rotated with the domain
  float decay = 1;              // exp(−damping·dt)
  float foamGain = 0, foamDecay = 1;
  float kick = 0;  // velocity Verlet: the fraction of dt·a added to the velocity (0.5, or 0: a alone)
  ContactUniforms contact;
  WallUniforms walls;
  NeighbourUniforms neighbours;
  static constexpr auto fields() {
    using U = CollideUniforms;
    return std::tuple{gl::field("uFirst", &U::first),
                      gl::field("uCount", &U::count),
                      gl::field("uGravity", &U::gravity),
                      gl::field("uDecay", &U::decay),
                      gl::field("uFoamGain", &U::foamGain),
                      gl::field("uFoamDecay", &U::foamDecay),
                      gl::field("uKick", &U::kick),
                      gl::field(&U::contact),
                      gl::field(&U::walls),
                      gl::field(&U::neighbours)};
  }
};

struct LoadsUniforms {          // balls/loads.comp
  GLuint first = 0, count = 0;  // balls [first, count)
  float radius = 0;             // m
  GLuint sourceFirst = 0;       // the first ball of the inputs' window
  ContactUniforms contact;
  WallUniforms walls;
  static constexpr auto fields() {
    using U = LoadsUniforms;
    return std::tuple{gl::field("uFirst", &U::first),   gl::field("uCount", &U::count),
                      gl::field("uRadius", &U::radius), gl::field("uSourceFirst", &U::sourceFirst),
                      gl::field(&U::contact),           gl::field(&U::walls)};
  }
};

struct ObstacleLoadsUniforms {  // balls/obstacle_loads.comp
  GLuint first = 0, count = 0;  // the balls counted: [first, count)
  float radius = 0;             // m
  GLuint sourceFirst = 0;       // the first ball of the inputs' window
  GLuint particles = 0;         // the obstacles' (water/obstacle_loads.glsl)
  GLuint add = 0;               // 1: add to the shares (a later window)
  ContactUniforms contact;
  grid::GridUniforms grid;
  static constexpr auto fields() {
    using U = ObstacleLoadsUniforms;
    return std::tuple{gl::field("uFirst", &U::first),
                      gl::field("uCount", &U::count),
                      gl::field("uRadius", &U::radius),
                      gl::field("uSourceFirst", &U::sourceFirst),
                      gl::field("uObstacleParticles", &U::particles),
                      gl::field("uAddShares", &U::add),
                      gl::field(&U::contact),
                      gl::field(&U::grid)};
  }
};

struct StatsUniforms {  // balls/stats.comp
  GLuint first = 0, count = 0;
  glm::vec3 gravity{0.0f}, domainMin{0.0f}, wallMin{0.0f}, wallMax{0.0f};
  NeighbourUniforms neighbours;
  static constexpr auto fields() {
    using U = StatsUniforms;
    return std::tuple{gl::field("uFirst", &U::first),     gl::field("uCount", &U::count),
                      gl::field("uGravity", &U::gravity), gl::field("uDomainMin", &U::domainMin),
                      gl::field("uWallMin", &U::wallMin), gl::field("uWallMax", &U::wallMax),
                      gl::field(&U::neighbours)};
  }
};

struct ReachUniforms {  // balls/reach_windows.comp
  GLuint windows = 0, windowSize = 0, count = 0, cells = 0;
  GLuint reach = 0;  // cells
  static constexpr auto fields() {
    using U = ReachUniforms;
    return std::tuple{gl::field("uWindows", &U::windows), gl::field("uWindowSize", &U::windowSize),
                      gl::field("uCount", &U::count), gl::field("uCells", &U::cells), gl::field("uReach", &U::reach)};
  }
};

}  // namespace tidepool::balls
