// The water both particle models run (balls: sim/balls, fluid: sim/fluid): domain, fill, walls
// and their motion, tap, obstacles, the engine's step, and the particle size. Each model's Params
// is a water::Setup plus its own physics; switching models keeps the setup (switched()). Declared
// once for JSON and UI through the visitors below, which each model places in its groups.
#pragma once

#include <array>
#include <cstddef>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "base/param.h"

namespace tidepool::water {

enum class Fill { Block, Slab, Random, Lattice, None };
constexpr std::array<const char*, 5> kFillNames = {"block", "slab", "random", "lattice", "none"};
enum class Shape { None, Sphere, Box, Capsule, Cup, Helix, Mesh };
constexpr std::array<const char*, 7> kShapeNames = {"none", "sphere", "box", "capsule", "cup", "helix", "mesh"};
enum class PathKind { None, Oscillate, Circle };
constexpr std::array<const char*, 3> kPathNames = {"none", "oscillate", "circle"};
constexpr std::size_t kMaxObstacles = 16;  // = BALLS_MAX_OBSTACLES (the pose block's size; obstacles.cpp checks)

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
// (centre, orientation, spin, path; sim/water/obstacle_pose.h), or, dynamic, from its motion.
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
  // A rigid body the water pushes (sim/water/bodies.h): gravity, the water and contacts move it
  // from its centre and orientation at rest; spin and path are then unused.
  bool dynamic = false;
  float density = 500.0f;  // kg/m³ of a dynamic obstacle
  // A hinge: a dynamic obstacle that only turns about this axis (world; zero: none, it moves freely)
  // through the point centre + hingeAt, both fixed in the world.
  glm::vec3 hingeAxis{0.0f};
  glm::vec3 hingeAt{0.0f};  // m
};
void visit(ParamVisitor& v, ObstacleParams& o);
// The parameters its particles are built from (a change rebuilds them; pose changes do not).
bool sameBody(const ObstacleParams& a, const ObstacleParams& b);

// A measurement the scene asks for (sim/water/probes.h says what each kind reads).
constexpr std::size_t kMaxProbes = 16;
enum class ProbeKind { Gauge, Pressure, Force, Body };
constexpr std::array<const char*, 4> kProbeKindNames = {"gauge", "pressure", "force", "body"};
enum class ProbeWall { None, MinX, MaxX, MinY, MaxY, MinZ, MaxZ };  // MinX..MaxZ: water::Loads::walls' order + 1
constexpr std::array<const char*, 7> kProbeWallNames = {"none", "-x", "+x", "-y", "+y", "-z", "+z"};
struct ProbeParams {
  ProbeKind kind = ProbeKind::Gauge;
  glm::vec3 at{0.5f, 0.5f, 0.0f};    // gauge: the line through (x, y); pressure: the point, m
  float radius = 0.0f;               // gauge: footprint radius R, m (0: five spacings)
  int obstacle = 0;                  // force, body: the obstacle's index in `obstacles`
  ProbeWall wall = ProbeWall::None;  // force: a wall instead of an obstacle
};

struct Setup {
  // Particles and domain
  float radius = 0.01f;                                 // r, m: the particle size (see "Particle size" below)
  glm::vec3 domainMin{0.0f}, domainMax{1.0f};           // box, m
  Fill fill = Fill::Block;                              // initial water
  glm::vec3 fillMin{0.0f}, fillMax{0.25f, 1.0f, 0.5f};  // block / random region, m
  float slabHeight = 0.2f;                              // slab: water up to this height, m
  int randomCount = 10000;                              // random fill: particles
  int latticeCount = 65536;                             // lattice (bench): particles on a cubic lattice at the corner
  float jitter = 0.001f;                                // initial position noise, fraction of r
  int maxParticles = 0;     // refuse larger requests before allocating (0: as many as the device holds)
  float resolution = 1.0f;  // the scene's spacing refined this many times (refine(); 1: as the scene sets it)
  // Engine
  float dt = 5e-4f;                       // s per step
  int substeps = 8;                       // steps per frame
  glm::vec3 gravity{0.0f, 0.0f, -9.81f};  // m/s^2 in the unrotated domain
  float damping = 0.0f;                   // 1/s: v *= exp(-damping dt)
  // Reproducible runs: the grid orders each cell's particles by index (grid/grid.h, GridParams::stable),
  // so every step sums in the same order and a run is bit-identical on the same GPU.
  bool deterministic = true;
  float foamGain = 1.0f, foamDecay = 0.997f;  // foam (for the renderer): grows with speed, decays; seed: 10
  // Walls: the piston moves one wall in and out; the domain may rotate about x (gravity follows)
  int pistonAxis = 0;         // 0 none, 1 x, 2 y, 3 z (the max wall of that axis)
  float pistonTravel = 0.5f;  // fraction of the domain the wall travels
  float pistonPeriod = 4.0f;  // s per in-and-out
  float rotation = 0.0f;      // degrees about x
  float rotationRate = 0.0f;  // degrees per s
  float contraction = 1.0f;   // the max wall on z at this fraction of the domain's height (the original's)
  // Obstacles: up to kMaxObstacles, each moving rigidly (sim/water/obstacles.h)
  std::vector<ObstacleParams> obstacles;
  // Tap: emits particles over time (up to tapMax in total) from a disc facing tapDirection
  bool tap = false;
  glm::vec3 tapPosition{0.5f, 0.5f, 0.05f};  // m
  glm::vec3 tapDirection{0.0f, 0.0f, 1.0f};
  float tapSpeed = 2.5f;    // m/s
  float tapRadius = 0.04f;  // nozzle radius, m
  int tapMax = 20000;       // particles the tap adds at most
  // Probes: gauges and obstacle poses, read by validate and export (sim/water/probes.h)
  std::vector<ProbeParams> probes;
};

// Particle size: one radius r in both models, what fills, obstacles, the tap, the grid and the
// renderer use. Neighbours at rest touch, so the spacing of particles at rest is d = 2r in both
// (the balls' contact distance, the fluid's `spacing` key); the models differ in how they pack:
// balls settle hexagonally (√2 particles per (2r)³), the fluid's rest lattice is cubic (one per d³).
enum class Packing { Cubic, Hcp };
inline float spacing(float radius) { return 2.0f * radius; }
inline float radiusOfSpacing(float spacing) { return 0.5f * spacing; }
float volumePerParticle(float radius, Packing packing);  // m³ per particle at rest
// The setup as the other model runs it (the window's model switch): everything but the time step,
// substeps and damping, which stay `own`'s (each model's stable step differs). The radius keeps the
// water's volume, a resting pile of balls being resting fluid and back: equal volumePerParticle,
// so r_hcp = r_cubic · 2^(1/6).
Setup switched(const Setup& from, Packing fromPacking, const Setup& own, Packing ownPacking);

// The visitors each model places in its groups (the keys without their group).
void visitFill(ParamVisitor& v, Setup& s);  // domain, fill, fill region, jitter, resolution, max particles
void visitEngine(ParamVisitor& v, Setup& s, float maxDt);  // dt (up to maxDt s), substeps, gravity, damping
void visitFoam(ParamVisitor& v, Setup& s);                 // foam gain and decay
void visitWalls(ParamVisitor& v, Setup& s);                // piston, rotation, contraction, "Reset domain"
// The original's "Reset domain": rotation 0, contraction 1, and the animations (rotation rate,
// piston) stopped, since here they are functions of the time, not steps from the current shape.
void resetDomain(Setup& s);
void visitTap(ParamVisitor& v, Setup& s);        // the tap's keys
void visitObstacles(ParamVisitor& v, Setup& s);  // the "obstacles" list

// Scenes that grow with the GPU: refines the spacing `factor` times keeping the physical setup
// (domain, fill region, water volume, obstacles, simulated time per frame). Radius ÷ f; the
// counts stated (random, lattice, tap) × f³; dt ÷ f and substeps × f, rounded, dt then set so that
// a frame stays dt · substeps. `resolution` records the product of the factors. Throws Error
// naming the limit a refinement would cross (2^30 particles, 1000 substeps per frame); `s` is then
// unchanged.
void refine(Setup& s, double factor);

}  // namespace tidepool::water
