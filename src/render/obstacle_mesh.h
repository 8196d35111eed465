// Triangle mesh of a balls obstacle, so the renderer can draw it as a surface instead of its fixed
// balls: a smoothed version of the union of its balls, running over the outer balls' tops and
// through the dimples between them (the water's balls stay outside it).
// Naive surface nets (Gibson 1998) over the distance to the nearest ball, sampled on a grid of
// spacing r: one vertex per grid cube the surface crosses (the mean of the crossings on its
// edges), one quad per crossed grid edge; then Taubin smoothing takes out the balls' bumps,
// normals are averaged from the faces around each vertex, and the surface moves in by 0.5 r:
//
//   distance(q) = min over balls |q - p| - 1.5 r     (< 0 inside; 1.5 r closes the packing's gaps)
//   edge (a, b) crossed when the signs differ; crossing at a + (b - a) d(a) / (d(a) - d(b))
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "gl/buffer.h"
#include "io/obj.h"
#include "sim/balls/balls.h"

namespace tidepool {

struct MeshVertex {
  glm::vec4 position;  // xyz m, in the balls' frame; w = 1
  glm::vec4 normal;    // xyz unit, outward; w = 0
};

// Triangles (three vertices each, counter-clockwise seen from outside) of the surface around
// `balls` (xyz centres, m). Closed whenever there is at least one ball. Empty for no balls.
std::vector<MeshVertex> ballUnionMesh(const std::vector<glm::vec4>& balls, float radius);

// A mesh file's triangles with their face normals (in the file's winding; the shader turns them
// toward the eye), for mesh obstacles: the renderer draws the shape itself, flat-shaded.
std::vector<MeshVertex> fileMesh(const io::TriangleMesh& mesh);

// A balls model's obstacle as a mesh on the GPU (in the obstacle's frame): a mesh obstacle's file
// triangles, any other shape the surface of the model's fixed particles. Rebuilt whenever the
// model rebuilds its obstacle (obstacleVersion()).
class ObstacleMesh {
 public:
  std::size_t update(const balls::Balls& model);  // vertex count
  const gl::Buffer& vertices() const { return m_vertices; }

 private:
  gl::Buffer m_vertices;
  std::size_t m_count = 0;
  bool m_built = false;
  unsigned m_version = 0;  // the model's obstacleVersion() built
};

}  // namespace tidepool
