// Mesh obstacles, after water-webgpu's fillable mesh (fillable-mesh.ts, ray-caster.ts): a closed
// triangle mesh, placed into the obstacle's box, fills with the HCP lattice points inside it; an
// open or closed one gives a shell of the lattice points near its surface.
//
// Inside test (the seed's): each lattice row (y, z) casts one ray along +x against the triangles
// projected onto the yz plane; the sorted crossings pair up into inside segments, cached per row.
// Where the seed takes strict barycentric interiors and drops near-duplicate hits, a ray through
// an edge or a vertex here is given to exactly one of the triangles around it: every edge test is
// evaluated in one canonical direction of the edge (so both triangles see the same number) and a
// zero is decided by a symbolic shift of the ray (y + ε, z + ε²). Every crossing then counts once,
// and rows through the mesh's own edges (a cube's face diagonals) are right.
#pragma once

#include <glm/glm.hpp>
#include <map>
#include <utility>
#include <vector>

#include "io/obj.h"

namespace tidepool::water {

// The mesh scaled uniformly so that its bounding box fits the half extents `size`, its box centre
// moved to `centre`, then turned by `orientation` about it.
io::TriangleMesh placeMesh(const io::TriangleMesh& mesh, glm::vec3 centre, glm::vec3 size,
                           const glm::mat3& orientation);

class MeshSolid {
 public:
  explicit MeshSolid(io::TriangleMesh placed);
  const io::TriangleMesh& mesh() const { return m_mesh; }
  // Ray parity along +x, for closed meshes. A point on the surface goes one way or the other
  // (segment ends are included, rows on the surface follow the tie-break).
  bool inside(glm::vec3 q) const;
  // Unsigned distance from q to the surface when it is below `limit`, else `limit` (m).
  float distance(glm::vec3 q, float limit) const;

 private:
  const std::vector<float>& row(float y, float z) const;  // inside segments [x0, x1, x2, x3, ...]
  io::TriangleMesh m_mesh;
  glm::vec3 m_lo, m_hi;
  // Triangles binned on the yz plane by their projected bounds, for the rows.
  glm::ivec2 m_bins{1};
  glm::vec2 m_binSize{1.0f};
  std::vector<std::vector<unsigned>> m_binTriangles;
  mutable std::map<std::pair<float, float>, std::vector<float>> m_rows;
};

// HCP lattice points (spacing 2r, hcpLattice's origin at the mesh's bounds − r) inside the mesh
// (solid) or within kShellHalfWidth·r of its surface (shell).
std::vector<glm::vec3> meshLatticePoints(const MeshSolid& solid, float r, bool shell);

// √2: the HCP lattice's covering radius in units of r (every point of space lies within √2·r of a
// lattice point, the centre of an octahedral hole being farthest). A band of this half width
// around the surface holds a lattice point within √2·r < 2r of every surface point, so no ball
// of radius r slips through the shell.
constexpr float kShellHalfWidth = 1.41421356f;

// Distance from q to triangle abc (Ericson, Real-Time Collision Detection, 5.1.5).
float pointTriangleDistance(glm::vec3 q, glm::vec3 a, glm::vec3 b, glm::vec3 c);

}  // namespace tidepool::water
