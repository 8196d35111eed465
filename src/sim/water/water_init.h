// Initial states of the water, built on the CPU: fills (block, slab, random, the CUDA sample's
// benchmark lattice) and obstacle particles from shapes or triangle meshes, on a hexagonal
// close-packed lattice (water-webgpu's strides: 2r, r·√3, 2r·√6/3) as a solid fill or a surface
// shell. The fluid fills blocks and slabs on its own cubic lattice (sim/fluid/fluid.cpp).
#pragma once

#include <functional>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "io/obj.h"
#include "sim/particle_memory.h"
#include "sim/water/setup.h"

namespace tidepool::water {

// Points of the HCP lattice of spacing 2r inside [lo, hi].
std::vector<glm::vec3> hcpLattice(glm::vec3 lo, glm::vec3 hi, float r);

class MeshSolid;

// One obstacle's particles in its own frame: the shape centred on the origin (the reference point
// of each shape: a cup's or helix's base centre, the others' middle), unturned; a mesh scaled
// into its box. ObstaclePose (obstacle_pose.h) places it in the world.
class Obstacle {
 public:
  // Reads a mesh shape's OBJ file: throws Error for a missing or malformed file, or an open mesh
  // asked for a solid fill (its message names the mesh and says what is not closed).
  Obstacle(const ObstacleParams& o, float radius);
  ~Obstacle();
  bool inside(glm::vec3 q) const;            // q (own frame) in the shape (analytic shapes: boundary included)
  std::vector<glm::vec4> particles() const;  // vec4: position m (own frame), w = 0
  // m³ of material: a solid sphere's, box's or capsule's in closed form, a closed mesh's enclosed
  // volume; shells, cups and helices: `particles` × the HCP lattice's volume per particle.
  double volume(std::size_t particles) const;
  const io::TriangleMesh* mesh() const;  // the scaled mesh of a mesh shape (own frame), else null

 private:
  ObstacleParams m_params;
  float m_radius;
  std::unique_ptr<MeshSolid> m_mesh;
};

// Before anything is built (sim/particle_memory.h checks these against what fits; `p` as the model
// runs it, balls::resolved for the balls):
double fillVolume(const Setup& p);      // m³ of a block or slab fill's region (0 for other fills)
double estimatedWater(const Setup& p);  // balls a fill makes: volume / (4√2 r³) on the HCP lattice
// An upper bound on the obstacles' particles: each obstacle's box (2 size per axis) filled solid.
double obstacleBound(const std::vector<ObstacleParams>& obstacles, float radius);
// The most particles of radius r a random fill's region (its centres' box, widened by r a side) or
// a lattice fill's domain holds: the region's volume / 4√2 r³, the volume per ball of hexagonal
// close packing (74 %, the densest there is; random close packing reaches 64 %), at least 1.
// Infinite for the other fills, which place particles on a lattice inside their region.
double fillCapacity(const Setup& p);
// The water's count check (balls, fluid), before anything is built: `fillParticles` (the fill's
// estimate) against fillCapacity (more would start on top of each other: every ball in a few grid
// cells, a first step of O(n²) pairs), then with the tap's maximum and the obstacles' bound
// against what fits; `size` names the key that sets the count ("particles.radius = 0.0001 m").
// Throws Error (sim/particle_memory.h).
void checkWaterRequest(const char* model, const char* particle, const std::string& size, double fillParticles,
                       const Setup& w, const sim::ParticleCost& cost);

// Water particles (vec4: position m, w = 1), none where `occupied` (inside an obstacle, say).
// Deterministic: same parameters, same particles.
std::vector<glm::vec4> waterParticles(const Setup& p, const std::function<bool(glm::vec3)>& occupied);

}  // namespace tidepool::water
