// Wavefront OBJ triangle meshes: vertex positions and faces; texture coordinates and normals are
// read past (and normals written: objBytes below). Polygons are fan-triangulated, negative indices count back from the
// last vertex:
//
//   v 0 0 0
//   v 1 0 0
//   v 0 1 0
//   f 1 2 3            # also f 1/1 2/2 3/3, f 1/1/1 2/2/1 3/3/1, f 1//1 2//1 3//1, f -3 -2 -1
//
// Errors are one line naming the file and line: "cube.obj:7: vertex index 9 out of range (8 defined so far)".
// Files over kMaxObjFileBytes, kMaxObjVertices vertices or kMaxObjTriangles triangles are refused (io/limits.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace tidepool::io {

struct TriangleMesh {
  std::vector<glm::vec3> vertices;    // positions, file units
  std::vector<glm::uvec3> triangles;  // 0-based vertex indices, in the file's winding
  std::vector<glm::vec3> normals;     // per vertex (unit, outward), or none
  glm::vec3 boundsMin() const;        // of the vertices that triangles use
  glm::vec3 boundsMax() const;
};

TriangleMesh parseObj(const std::string& text, const std::string& name);  // throws Error "name:line: ..."
TriangleMesh readObj(const std::filesystem::path& path);                  // throws Error (missing file, bad input)

// A closed mesh has every edge shared by exactly two triangles: it bounds a volume, so a point
// is inside when a ray from it crosses the surface an odd number of times. Vertices at the same
// position count as one (files often split them along texture seams).
struct EdgeCheck {
  std::size_t edges = 0;             // distinct edges
  std::size_t boundaryEdges = 0;     // used by one triangle only: a hole
  std::size_t nonManifoldEdges = 0;  // used by three or more triangles
  glm::uvec2 firstBad{0};            // 1-based vertex numbers (as in the file) of the first bad edge
  bool closed() const { return boundaryEdges == 0 && nonManifoldEdges == 0; }
  std::string describe() const;  // "not closed: 4 edges belong to one triangle only (a hole), first 3-7"
};
EdgeCheck checkClosed(const TriangleMesh& mesh);

// The mesh as OBJ text: a comment line (`comment`, e.g. "tidepool time 0.5", when not empty),
// "v x y z" per vertex, "vn nx ny nz" per vertex when it has normals, then "f a//a b//b c//c"
// (1-based; "f a b c" without normals). Blender and ParaView import it.
std::vector<std::uint8_t> objBytes(const TriangleMesh& mesh, const std::string& comment = "");
void writeObj(const std::filesystem::path& file, const TriangleMesh& mesh, const std::string& comment = "");

// A mesh named in a scene: an absolute or existing path as given, else assets/meshes/<name>
// (".obj" may be left out). Throws Error listing the meshes there.
std::filesystem::path findMesh(const std::string& nameOrPath);

}  // namespace tidepool::io
