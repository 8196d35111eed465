// Initial states of the balls model, built on the CPU: water fills (block, slab, random, the CUDA
// sample's benchmark lattice) and obstacle particles from shapes or triangle meshes, on a
// hexagonal close-packed lattice (water-webgpu's strides: 2r, r·√3, 2r·√6/3) as a solid fill or a
// surface shell.
#pragma once

#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "io/obj.h"
#include "sim/balls/balls_params.h"

namespace tidepool::balls {

// Points of the HCP lattice of spacing 2r inside [lo, hi].
std::vector<glm::vec3> hcpLattice(glm::vec3 lo, glm::vec3 hi, float r);

// The lattice fill's derived radius and gravity (CUDA sample: r = width/(2G), g x 64/G with G
// the next power of two >= ceil(N^(1/3))). Other fills return the parameters unchanged.
Params resolved(const Params& p);

class MeshSolid;

// The obstacle at rest (its own frame = the world at spin angle 0): the shape turned by its
// orientation about its centre, or the mesh placed into its box.
class Obstacle {
 public:
  // Reads a mesh shape's OBJ file: throws Error for a missing or malformed file, or an open mesh
  // asked for a solid fill (its message names the mesh and says what is not closed).
  explicit Obstacle(const Params& p);
  ~Obstacle();
  bool inside(glm::vec3 q) const;            // q in the shape (analytic shapes: boundary included)
  std::vector<glm::vec4> particles() const;  // vec4: position m, w = 0 (immovable)
  const io::TriangleMesh* mesh() const;      // the placed mesh of a mesh shape, else null

 private:
  bool insideShape(glm::vec3 q) const;  // analytic shapes in their unturned frame
  Params m_params;
  glm::mat3 m_orientation{1.0f};  // shape -> obstacle frame, about the centre
  bool m_turned = false;
  std::unique_ptr<MeshSolid> m_mesh;
};

glm::mat3 orientationMatrix(glm::vec3 degrees);  // about x, then y, then z

// Water particles (vec4: position m, w = 1), none inside the obstacle. Deterministic: same
// parameters, same particles.
std::vector<glm::vec4> waterParticles(const Params& p, const Obstacle& obstacle);

}  // namespace tidepool::balls
