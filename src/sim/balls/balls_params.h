// Parameters of the balls model: N equal balls of radius r in a box, contact model, integrator,
// walls (movable), gravity (rotating with the domain), damping; declared once for JSON and UI.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "balls/bindings.glsl"
#include "base/param.h"

namespace tidepool::balls {

enum class Contact { Penalty, SpringDashpot, CudaSample };
constexpr std::array<const char*, 3> kContactNames = {"penalty", "spring-dashpot", "cuda-sample"};
enum class Integrator { ExplicitEuler, SymplecticEuler, VelocityVerlet };
constexpr std::array<const char*, 3> kIntegratorNames = {"explicit-euler", "symplectic-euler", "verlet"};
enum class Fill { Block, Slab, Random, Lattice, None };
constexpr std::array<const char*, 5> kFillNames = {"block", "slab", "random", "lattice", "none"};
enum class Shape { None, Sphere, Box, Capsule, Cup, Helix, Mesh };
constexpr std::array<const char*, 7> kShapeNames = {"none", "sphere", "box", "capsule", "cup", "helix", "mesh"};
enum class PathKind { None, Oscillate, Circle };
constexpr std::array<const char*, 3> kPathNames = {"none", "oscillate", "circle"};
constexpr std::size_t kMaxObstacles = BALLS_MAX_OBSTACLES;

// A periodic translation of an obstacle's centre, θ = 2π·t/period + phase:
//   oscillate  centre + amplitude·sin θ                        (to and fro along the amplitude)
//   circle     centre + (a.x·cos θ, a.y·sin θ, a.z·sin θ)       (a circle or ellipse about it)
struct ObstaclePath {
  PathKind kind = PathKind::None;
  glm::vec3 amplitude{0.1f, 0.0f, 0.0f};  // m
  float period = 2.0f;                    // s
  float phase = 0.0f;                     // degrees
};

// One obstacle: fixed particles from a shape, built once in the obstacle's own frame (shape,
// mesh, shell, size), and a rigid pose that may change every step without rebuilding them
// (centre, orientation, spin, path; sim/balls/obstacle_pose.h).
struct ObstacleParams {
  Shape shape = Shape::Sphere;
  std::string mesh = "torus";  // mesh: OBJ in assets/meshes (".obj" optional) or a path
  bool shell = false;          // a surface shell instead of a solid fill
  glm::vec3 centre{0.5f, 0.5f, 0.4f};
  glm::vec3 size{0.1f, 0.1f, 0.1f};  // half extents (box, mesh bounds), radius (x) and height (z), per shape
  glm::vec3 orientation{0.0f};       // degrees about x, then y, then z, turning the shape about its centre
  float spin = 0.0f;                 // rad/s about spinAxis through the (moving) centre
  glm::vec3 spinAxis{0.0f, 0.0f, 1.0f};
  ObstaclePath path;
};
void visit(ParamVisitor& v, ObstacleParams& o);
// The parameters its particles are built from (a change rebuilds them; pose changes do not).
bool sameBody(const ObstacleParams& a, const ObstacleParams& b);

struct Params {
  // Particles and domain
  float radius = 0.01f;                                 // r, m
  glm::vec3 domainMin{0.0f}, domainMax{1.0f};           // box, m
  Fill fill = Fill::Block;                              // initial water
  glm::vec3 fillMin{0.0f}, fillMax{0.25f, 1.0f, 0.5f};  // block / random region, m
  float slabHeight = 0.2f;                              // slab: water up to this height, m
  int randomCount = 10000;                              // random fill: particles
  int latticeCount = 65536;                             // lattice (bench): particles on a cubic lattice at the corner
  bool latticeScaling = true;                           // lattice: r = width/(2G), gravity x 64/G (CUDA sample)
  float jitter = 0.001f;                                // initial position noise, fraction of r
  int maxParticles = 0;     // refuse larger requests before allocating (0: as many as the device holds)
  float resolution = 1.0f;  // the scene's spacing refined this many times (refine(); 1: as the scene sets it)
  // Engine
  Contact contact = Contact::SpringDashpot;
  Integrator integrator = Integrator::SymplecticEuler;
  float dt = 5e-4f;                       // s per step
  int substeps = 8;                       // steps per frame
  glm::vec3 gravity{0.0f, 0.0f, -9.81f};  // m/s^2 in the unrotated domain
  float damping = 0.0f;                   // 1/s: v *= exp(-damping dt)
  // Reproducible runs: the grid orders each cell's balls by index (grid/grid.h, GridParams::stable),
  // so every step sums contacts in the same order and a run is bit-identical on the same GPU.
  bool deterministic = true;
  // spring-dashpot: k and gamma from the contact duration and restitution (per unit effective mass)
  float contactTime = 0.01f;  // t_c, s
  float restitution = 0.5f;   // e
  float friction = 0.0f;      // Coulomb coefficient (tangential), 0: frictionless
  // penalty (the seed's): velocity change 0.96 * share * overlap per step; walls 2 * overlap
  float penaltyFactor = 0.96f;
  // cuda-sample: per-step velocity changes (NVIDIA CUDA "particles" sample)
  float cudaSpring = 0.5f, cudaDamping = 0.02f, cudaShear = 0.1f, cudaBoundaryDamping = -0.5f;
  // Walls: the piston moves one wall in and out; the domain may rotate about x (gravity follows)
  int pistonAxis = 0;         // 0 none, 1 x, 2 y, 3 z (the max wall of that axis)
  float pistonTravel = 0.5f;  // fraction of the domain the wall travels
  float pistonPeriod = 4.0f;  // s per in-and-out
  float rotation = 0.0f;      // degrees about x
  float rotationRate = 0.0f;  // degrees per s
  float contraction = 1.0f;   // the max wall on z at this fraction of the domain's height (the original's)
  // Obstacles: up to kMaxObstacles, each moving rigidly (src/sim/balls/obstacles.h)
  std::vector<ObstacleParams> obstacles;
  // Tap: emits balls over time (up to tapMax in total) from a disc facing tapDirection
  bool tap = false;
  glm::vec3 tapPosition{0.5f, 0.5f, 0.05f};  // m
  glm::vec3 tapDirection{0.0f, 0.0f, 1.0f};
  float tapSpeed = 2.5f;    // m/s
  float tapRadius = 0.04f;  // nozzle radius, m
  int tapMax = 20000;       // balls the tap adds at most
  // Foam (for the renderer): grows with speed, decays
  float foamGain = 1.0f, foamDecay = 0.997f;  // seed: 10 in its slower units
};

void visit(ParamVisitor& v, Params& p);
// The parts the fluid model shares (sim/fluid/fluid_params.h), each without its group.
void visitFill(ParamVisitor& v, Params& p);   // domain, fill, fill region, jitter, max particles
void visitWalls(ParamVisitor& v, Params& p);  // piston, rotation, contraction, "Reset domain"
// The original's "Reset domain": rotation 0, contraction 1, and the animations (rotation rate,
// piston) stopped, since here they are functions of the time, not steps from the current shape.
void resetDomain(Params& p);
void visitTap(ParamVisitor& v, Params& p);        // the tap's keys
void visitObstacles(ParamVisitor& v, Params& p);  // the "obstacles" list

// Scenes that grow with the GPU: refines the spacing `factor` times keeping the physical setup
// (domain, fill region, water volume, obstacles, simulated time per frame). Radius ÷ f; the
// counts stated (random, lattice, tap) × f³; contact time ÷ f (contact stiffness of a material:
// t_c ∝ r keeps the overlap under a column of water the same fraction of r) and with it dt ÷ f and
// substeps × f, rounded, dt then set so that a frame stays dt · substeps. `resolution` records the
// product of the factors. Throws Error naming the limit a refinement would cross (2^30 particles,
// 1000 substeps per frame); `p` is then unchanged.
void refine(Params& p, double factor);

// Spring constant and dashpot coefficient per unit effective mass from t_c and e:
//   k = (pi^2 + ln^2 e) / t_c^2,  gamma = -2 ln e / t_c   (linear spring-dashpot, exact t_c and e)
inline float springPerMass(const Params& p) {
  const float le = std::log(std::max(p.restitution, 1e-6f));
  return (9.8696044f + le * le) / (p.contactTime * p.contactTime);
}
inline float dashpotPerMass(const Params& p) {
  return -2.0f * std::log(std::max(p.restitution, 1e-6f)) / p.contactTime;
}

}  // namespace tidepool::balls
