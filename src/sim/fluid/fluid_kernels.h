// The uniforms of the fluid's kernels (gl/kernel.h): one struct per kernel, built from the parts
// its includes declare (fluid/kernels.glsl, walls.glsl, neighbours.glsl, boundary.glsl). A field
// names its GLSL uniform once; the program is checked against the struct when it is built.
#pragma once

#include <array>

#include "common/obstacle_bindings.glsl"
#include "gl/kernel.h"
#include "grid/grid.h"
#include "sim/fluid/rest_lattice.h"
#include "sim/water/obstacles.h"

namespace tidepool::fluid {

struct SphUniforms {                      // fluid/kernels.glsl
  float h = 0;                            // smoothing radius, m
  float poly6 = 0;                        // 315 / (64 π h³)
  float spiky = 0;                        // −45 / (π h⁴)
  float volume = 0;                       // V0 of a fluid particle, m³
  std::array<glm::vec4, 73> edgeTable{};  // Q(a, b) of the walls' shared quarter spaces, 4 per vec4
  static constexpr auto fields() {
    using U = SphUniforms;
    return std::tuple{gl::field("uH", &U::h), gl::field("uPoly6Coef", &U::poly6), gl::field("uSpikyCoef", &U::spiky),
                      gl::field("uVolume", &U::volume), gl::field("uEdgeTable", &U::edgeTable)};
  }
};
SphUniforms sphUniforms(double h, const RestLattice& rest);

struct WallUniforms {              // fluid/walls.glsl
  glm::vec3 min{0.0f}, max{0.0f};  // current wall positions, m
  float scale = 1;                 // makes a resting lattice's first layer read ρ0
  float inset = 0;                 // d / 2, m
  static constexpr auto fields() {
    using U = WallUniforms;
    return std::tuple{gl::field("uWallMin", &U::min), gl::field("uWallMax", &U::max),
                      gl::field("uWallScale", &U::scale), gl::field("uWallInset", &U::inset)};
  }
};

struct NeighbourUniforms {  // fluid/neighbours.glsl
  GLint reach = 0;          // cells each way that cover h
  grid::GridUniforms grid;
  static constexpr auto fields() {
    using U = NeighbourUniforms;
    return std::tuple{gl::field("uReach", &U::reach), gl::field(&U::grid)};
  }
};

struct BoundaryUniforms {  // fluid/boundary.glsl
  GLint reach = 0;         // obstacle-grid cells each way that cover h
  GLint volumes = OBSTACLE_VOLUME_UNIT;
  water::ObstacleUniforms obstacles;
  static constexpr auto fields() {
    using U = BoundaryUniforms;
    return std::tuple{gl::field("uObstacleReach", &U::reach), gl::field("obstacleVolume", &U::volumes),
                      gl::field(&U::obstacles)};
  }
};
// Binds the obstacles' textures (when active) and returns what boundary.glsl reads for support h.
BoundaryUniforms bindBoundary(const water::Obstacles& obstacles, double h);
// HAS_OBSTACLE and OBSTACLE_VOLUMES, for the kernels that include boundary.glsl.
std::vector<gl::ShaderDefine> boundaryDefines(const water::Obstacles& obstacles);

struct PredictUniforms {  // fluid/predict.comp
  GLuint count = 0;
  float dt = 0;
  glm::vec3 gravity{0.0f};  // m/s², turned with the domain
  float decay = 1;          // exp(−damping·dt)
  SphUniforms sph;
  WallUniforms walls;
  static constexpr auto fields() {
    using U = PredictUniforms;
    return std::tuple{gl::field("uCount", &U::count), gl::field("uDt", &U::dt), gl::field("uGravity", &U::gravity),
                      gl::field("uDecay", &U::decay), gl::field(&U::sph),       gl::field(&U::walls)};
  }
};

struct LambdaUniforms {  // fluid/lambda.comp
  GLuint count = 0;
  float epsilon = 0;          // ε, 1/m²
  GLuint firstIteration = 0;  // 1: the sum of λ over the iterations starts anew
  SphUniforms sph;
  WallUniforms walls;
  NeighbourUniforms neighbours;
  BoundaryUniforms boundary;
  static constexpr auto fields() {
    using U = LambdaUniforms;
    return std::tuple{gl::field("uCount", &U::count),
                      gl::field("uEpsilon", &U::epsilon),
                      gl::field("uFirstIteration", &U::firstIteration),
                      gl::field(&U::sph),
                      gl::field(&U::walls),
                      gl::field(&U::neighbours),
                      gl::field(&U::boundary)};
  }
};

struct DeltaUniforms {  // fluid/delta.comp
  GLuint count = 0;
  float scorrK = 0, scorrN = 0;
  float scorrInvQ = 0;  // 1 / (1 − Δq²/h²)
  float contact = 0;    // m: the closest a fluid particle comes to an obstacle particle
  SphUniforms sph;
  WallUniforms walls;
  NeighbourUniforms neighbours;
  BoundaryUniforms boundary;
  static constexpr auto fields() {
    using U = DeltaUniforms;
    return std::tuple{gl::field("uCount", &U::count),
                      gl::field("uScorrK", &U::scorrK),
                      gl::field("uScorrN", &U::scorrN),
                      gl::field("uScorrInvQ", &U::scorrInvQ),
                      gl::field("uContact", &U::contact),
                      gl::field(&U::sph),
                      gl::field(&U::walls),
                      gl::field(&U::neighbours),
                      gl::field(&U::boundary)};
  }
};

struct ObstacleLoadsUniforms {  // fluid/obstacle_loads.comp
  GLuint particles = 0;         // the obstacles' (water/obstacle_loads.glsl)
  GLuint add = 0;               // 1: add to the shares (a later iteration)
  float contact = 0;            // m: the closest a fluid particle comes to an obstacle particle
  SphUniforms sph;
  NeighbourUniforms neighbours;
  static constexpr auto fields() {
    using U = ObstacleLoadsUniforms;
    return std::tuple{gl::field("uObstacleParticles", &U::particles), gl::field("uAddShares", &U::add),
                      gl::field("uContact", &U::contact), gl::field(&U::sph), gl::field(&U::neighbours)};
  }
};

struct VelocityUniforms {  // fluid/velocity.comp
  GLuint count = 0;
  float dt = 0, foamGain = 0, foamDecay = 1, sprayDensity = 0;
  static constexpr auto fields() {
    using U = VelocityUniforms;
    return std::tuple{gl::field("uCount", &U::count), gl::field("uDt", &U::dt), gl::field("uFoamGain", &U::foamGain),
                      gl::field("uFoamDecay", &U::foamDecay), gl::field("uSprayDensity", &U::sprayDensity)};
  }
};

struct ViscosityUniforms {  // fluid/viscosity.comp
  GLuint count = 0;
  float viscosity = 0;  // XSPH c
  SphUniforms sph;
  NeighbourUniforms neighbours;
  static constexpr auto fields() {
    using U = ViscosityUniforms;
    return std::tuple{gl::field("uCount", &U::count), gl::field("uViscosity", &U::viscosity), gl::field(&U::sph),
                      gl::field(&U::neighbours)};
  }
};

struct VorticityUniforms {  // fluid/vorticity.comp
  GLuint count = 0;
  float dt = 0;
  float vorticity = 0;  // ε_v, m/s
  SphUniforms sph;
  NeighbourUniforms neighbours;
  static constexpr auto fields() {
    using U = VorticityUniforms;
    return std::tuple{gl::field("uCount", &U::count), gl::field("uDt", &U::dt), gl::field("uVorticity", &U::vorticity),
                      gl::field(&U::sph), gl::field(&U::neighbours)};
  }
};

struct StatsUniforms {  // fluid/stats.comp
  GLuint count = 0;
  glm::vec3 gravity{0.0f}, domainMin{0.0f};
  float spacing = 0;  // m
  SphUniforms sph;
  WallUniforms walls;
  NeighbourUniforms neighbours;
  BoundaryUniforms boundary;
  static constexpr auto fields() {
    using U = StatsUniforms;
    return std::tuple{gl::field("uCount", &U::count),
                      gl::field("uGravity", &U::gravity),
                      gl::field("uDomainMin", &U::domainMin),
                      gl::field("uSpacing", &U::spacing),
                      gl::field(&U::sph),
                      gl::field(&U::walls),
                      gl::field(&U::neighbours),
                      gl::field(&U::boundary)};
  }
};

}  // namespace tidepool::fluid
