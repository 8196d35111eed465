#include "render/marching_cubes.h"

#include "base/error.h"

namespace tidepool::mc {
namespace {

int cornerAt(glm::ivec3 p) { return p.x | (p.y << 1) | (p.z << 2); }

int edgeBetween(int a, int b) {  // corners that differ along one axis
  const glm::ivec3 pa = cornerOffset(a), pb = cornerOffset(b);
  const glm::ivec3 start = glm::min(pa, pb);
  for (int axis = 0; axis < 3; ++axis) {
    if (pa[axis] == pb[axis]) continue;
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    return axis * 4 + start[u] + 2 * start[v];
  }
  throw Error("marching cubes: corners " + std::to_string(a) + " and " + std::to_string(b) + " are not an edge");
}

// Corners of face (axis, side), counter-clockwise seen from outside the cube.
std::array<int, 4> faceCorners(int axis, int side) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  std::array<int, 4> out{};
  const int uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // counter-clockwise seen from +axis (u x v = axis)
  for (int i = 0; i < 4; ++i) {
    glm::ivec3 p(0);
    p[axis] = side;
    p[u] = uv[side ? i : 3 - i][0];
    p[v] = uv[side ? i : 3 - i][1];
    out[i] = cornerAt(p);
  }
  return out;
}

// Do edges a and b lie on a common face of the cube? (Edge e lies on the faces across its two
// other axes, at its start's coordinates there.)
bool onOneFace(int a, int b) {
  for (int axis = 0; axis < 3; ++axis)
    if (edgeAxis(a) != axis && edgeAxis(b) != axis && edgeStart(a)[axis] == edgeStart(b)[axis]) return true;
  return false;
}

Case buildCase(int bits) {
  const auto inside = [bits](int corner) { return (bits >> corner & 1) != 0; };
  // next[e]: the cut starting at edge e's crossing (where a face walk enters the inside) ends at
  // next[e] (where that walk leaves it). Each crossing starts one cut and ends one (its two faces).
  std::array<int, 12> next;
  next.fill(-1);
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const std::array<int, 4> c = faceCorners(axis, side);
      for (int i = 0; i < 4; ++i) {
        if (inside(c[i]) || !inside(c[(i + 1) % 4])) continue;  // not an entry: outside -> inside
        int j = (i + 1) % 4;                                    // walk on through the inside corners to the exit
        while (inside(c[(j + 1) % 4])) j = (j + 1) % 4;
        const int from = edgeBetween(c[i], c[(i + 1) % 4]), to = edgeBetween(c[j], c[(j + 1) % 4]);
        if (next[from] != -1) throw Error("marching cubes: edge " + std::to_string(from) + " starts two cuts");
        next[from] = to;
      }
    }
  Case out;
  std::array<bool, 12> used{};
  for (int start = 0; start < 12; ++start) {
    if (next[start] < 0 || used[start]) continue;
    std::vector<int> loop;
    for (int e = start; !used[e]; e = next[e]) {
      used[e] = true;
      loop.push_back(e);
    }
    // Cut off ears (a, b, c) whose new side a-c does not lie on a face of the cube: where a loop
    // crosses an ambiguous face twice, a side there would be shared with the neighbouring cell's
    // triangles (a pinch). Sides inside the cube are this cell's alone, so the mesh stays manifold.
    while (loop.size() >= 3) {
      std::size_t ear = 0;
      while (loop.size() > 3 && ear < loop.size() && onOneFace(loop[ear], loop[(ear + 2) % loop.size()])) ++ear;
      if (ear == loop.size()) throw Error("marching cubes: case " + std::to_string(bits) + " has no ear to cut");
      if (out.triangles == kMaxTriangles) throw Error("marching cubes: case " + std::to_string(bits) + " overflows");
      const int t = out.triangles++;
      for (int k = 0; k < 3; ++k) out.edges[3 * t + k] = std::uint8_t(loop[(ear + k) % loop.size()]);
      loop.erase(loop.begin() + std::ptrdiff_t((ear + 1) % loop.size()));
      if (loop.size() < 3) break;
    }
  }
  return out;
}

}  // namespace

glm::ivec3 cornerOffset(int corner) { return {corner & 1, (corner >> 1) & 1, (corner >> 2) & 1}; }

int edgeAxis(int edge) { return edge / 4; }

glm::ivec3 edgeStart(int edge) {
  const int axis = edgeAxis(edge);
  glm::ivec3 p(0);
  p[(axis + 1) % 3] = edge & 1;
  p[(axis + 2) % 3] = (edge >> 1) & 1;
  return p;
}

int edgeCorner(int edge, int end) {
  glm::ivec3 p = edgeStart(edge);
  p[edgeAxis(edge)] = end;
  return cornerAt(p);
}

const std::array<Case, 256>& caseTable() {
  static const std::array<Case, 256> table = [] {
    std::array<Case, 256> t;
    for (int bits = 0; bits < 256; ++bits) t[bits] = buildCase(bits);
    return t;
  }();
  return table;
}

std::vector<glm::uvec4> packedCaseTable() {
  std::vector<glm::uvec4> out(256, glm::uvec4(0));
  for (int bits = 0; bits < 256; ++bits) {
    const Case& c = caseTable()[bits];
    const auto put = [&](int nibble, unsigned value) { out[bits][nibble / 8] |= value << (4 * (nibble % 8)); };
    put(0, unsigned(c.triangles));
    for (int k = 0; k < 3 * c.triangles; ++k) put(1 + k, c.edges[k]);
  }
  return out;
}

}  // namespace tidepool::mc
