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
#include <utility>
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

// The vertices' bounds (min, max); empty (min > max) for no vertices.
std::pair<glm::vec3, glm::vec3> meshBounds(const std::vector<MeshVertex>& mesh);

// A balls model's obstacles as meshes on the GPU, one per obstacle in its own frame (its pose
// places it, every frame, without rebuilding): a mesh obstacle's file triangles, any other shape
// the surface of its fixed particles. An obstacle's mesh is built once per build of its particles
// (ObstacleBody::id), so moving, turning, adding or removing others rebuilds nothing.
class ObstacleMeshes {
 public:
  void update(const water::Obstacles& obstacles, float radius);  // the meshes of the obstacles' bodies
  std::size_t size() const { return m_meshes.size(); }
  const gl::Buffer& vertices(std::size_t k) const { return m_meshes[k].vertices; }  // of obstacles.body(k)
  std::size_t count(std::size_t k) const { return m_meshes[k].count; }              // vertices
  glm::vec3 boundsMin(std::size_t k) const { return m_meshes[k].lo; }               // own frame; empty mesh: min > max
  glm::vec3 boundsMax(std::size_t k) const { return m_meshes[k].hi; }
  std::size_t builds() const { return m_builds; }  // meshes built so far (tests: none per frame)

 private:
  struct Entry {
    unsigned id = 0;  // ObstacleBody::id
    gl::Buffer vertices;
    std::size_t count = 0;
    glm::vec3 lo{1.0f}, hi{-1.0f};  // the vertices' bounds
  };
  std::vector<Entry> m_meshes;
  std::size_t m_builds = 0;
};

}  // namespace tidepool
