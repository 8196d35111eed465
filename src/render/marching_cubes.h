// Marching cubes (Lorensen & Cline 1987) with a case table built here, not typed in: for each of the
// 256 inside/outside patterns of a cube's corners, walk the six faces, cut each face between its
// inside and outside corners, chain the cuts into loops and fan each loop into triangles. Both
// the CPU reference (tests/reference/surface_reference.h) and the GPU kernels (shaders/surface/) read this table.
//
// Numbering (the same formulas in shaders/surface/cube.glsl):
//   corner k (0..7) sits at (k & 1, (k >> 1) & 1, (k >> 2) & 1) in the cell
//   edge e (0..11) runs along axis a = e / 4 from the corner whose a-coordinate is 0 and whose
//   other coordinates u = (a + 1) % 3, v = (a + 2) % 3 are (e & 1, (e >> 1) & 1)
//
// Why it is watertight and consistently oriented: a face's cuts depend only on that face's four
// corners, which the two cells sharing it see alike; on a face with two diagonal inside corners
// the cuts keep the inside corners apart (both cells make the same choice). Each face is walked
// counter-clockwise seen from outside its cell and a cut runs from where the walk enters the inside
// to where it leaves it, so the two cells sharing a face run each shared cut in opposite directions
// (the neighbouring triangles agree), and every triangle faces away from the inside (its
// counter-clockwise side looks toward lower density): outward normals for water.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tidepool::mc {

inline constexpr int kMaxTriangles = 10;  // per case (a row of the packed table holds 31 edges)

struct Case {
  int triangles = 0;                                    // 0..kMaxTriangles
  std::array<std::uint8_t, 3 * kMaxTriangles> edges{};  // 3 edges per triangle, counter-clockwise from outside
};

const std::array<Case, 256>& caseTable();  // built once

// The table as the GPU reads it (std140 uniform block of 256 uvec4): per case, 4-bit nibbles,
// nibble 0 the triangle count, nibbles 1.. the edges in order (word = nibble / 8).
std::vector<glm::uvec4> packedCaseTable();

glm::ivec3 cornerOffset(int corner);  // (k & 1, (k >> 1) & 1, (k >> 2) & 1)
int edgeAxis(int edge);               // e / 4
glm::ivec3 edgeStart(int edge);       // the corner the edge runs from (its owner in the grid)
int edgeCorner(int edge, int end);    // the edge's corner numbers: end 0 = start, 1 = start + axis

}  // namespace tidepool::mc
