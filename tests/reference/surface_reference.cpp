#include "reference/surface_reference.h"

#include <cmath>

#include "render/marching_cubes.h"
#include "surface/bindings.glsl"

namespace tidepool {
namespace {

struct Field {
  const std::vector<std::uint32_t>& density;
  const SurfaceGrid& grid;
  float iso;

  std::size_t index(glm::ivec3 c) const {
    return std::size_t(c.x) + grid.corners.x * (std::size_t(c.y) + std::size_t(grid.corners.y) * c.z);
  }
  float at(glm::ivec3 c) const {  // cube.glsl's densityAt
    c = glm::clamp(c, glm::ivec3(0), glm::ivec3(grid.corners) - 1);
    for (int a = 0; a < 3; ++a)
      if (c[a] == 0 || c[a] == int(grid.corners[a]) - 1) return 0.0f;
    return float(density[index(c)]) / float(SURFACE_FIXED_ONE);
  }
  bool inside(glm::ivec3 c) const { return at(c) > iso; }
  bool crosses(glm::ivec3 c, int axis) const {
    glm::ivec3 b = c;
    ++b[axis];
    return inside(c) != inside(b);
  }
  unsigned cellCase(glm::ivec3 c) const {
    unsigned bits = 0;
    for (int k = 0; k < 8; ++k)
      if (inside(c + mc::cornerOffset(k))) bits |= 1u << k;
    return bits;
  }
  glm::vec3 gradient(glm::ivec3 c) const {
    const glm::ivec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    return {at(c + x) - at(c - x), at(c + y) - at(c - y), at(c + z) - at(c - z)};
  }
};

}  // namespace

std::vector<std::uint32_t> splatReference(const std::vector<glm::vec4>& positions, const SurfaceGrid& grid) {
  std::vector<std::uint32_t> density(grid.cornerCount(), 0);
  const float reach = grid.h / grid.cell, invH2 = 1.0f / (grid.h * grid.h);
  const glm::vec3 top = glm::vec3(grid.corners) - 2.0f;
  for (const glm::vec4& p : positions) {
    const glm::vec3 g = (glm::vec3(p) - grid.origin) / grid.cell;
    if (!std::isfinite(g.x) || !std::isfinite(g.y) || !std::isfinite(g.z)) continue;
    const glm::ivec3 lo(glm::clamp(glm::ceil(g - reach), glm::vec3(1.0f), top + 1.0f));
    const glm::ivec3 hi(glm::clamp(glm::floor(g + reach), glm::vec3(0.0f), top));
    for (int z = lo.z; z <= hi.z; ++z)
      for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) {
          const glm::vec3 d = (glm::vec3(x, y, z) - g) * grid.cell;
          const float q2 = glm::dot(d, d) * invH2;
          if (q2 >= 1.0f) continue;
          const float w = (1.0f - q2) * (1.0f - q2) * (1.0f - q2);
          density[std::size_t(x) + grid.corners.x * (std::size_t(y) + std::size_t(grid.corners.y) * z)] +=
              std::uint32_t(w * grid.weightOne + 0.5f);
        }
  }
  return density;
}

io::TriangleMesh marchReference(const std::vector<std::uint32_t>& density, const SurfaceGrid& grid, float iso) {
  const Field f{density, grid, iso};
  const glm::ivec3 last = glm::ivec3(grid.corners) - 1;
  io::TriangleMesh mesh;
  std::vector<std::uint32_t> firstVertex(grid.cornerCount() + 1, 0);  // the scanned vertex counts
  for (int z = 0; z <= last.z; ++z)
    for (int y = 0; y <= last.y; ++y)
      for (int x = 0; x <= last.x; ++x) {
        const glm::ivec3 c(x, y, z);
        firstVertex[f.index(c)] = std::uint32_t(mesh.vertices.size());
        for (int axis = 0; axis < 3; ++axis) {
          if (c[axis] >= last[axis] || !f.crosses(c, axis)) continue;
          glm::ivec3 b = c;
          ++b[axis];
          const float da = f.at(c), db = f.at(b), t = (iso - da) / (db - da);
          glm::vec3 p(c);
          p[axis] += t;
          const glm::vec3 g = glm::mix(f.gradient(c), f.gradient(b), t);
          const float len = glm::length(g);
          glm::vec3 n(0.0f);
          n[axis] = da > db ? 1.0f : -1.0f;
          mesh.vertices.push_back(grid.origin + p * grid.cell);
          mesh.normals.push_back(len > 0.0f ? -g / len : n);
        }
      }
  const auto vertexOn = [&](glm::ivec3 c, int e) {
    const glm::ivec3 owner = c + mc::edgeStart(e);
    std::uint32_t rank = 0;
    for (int a = 0; a < mc::edgeAxis(e); ++a) rank += f.crosses(owner, a) ? 1 : 0;
    return firstVertex[f.index(owner)] + rank;
  };
  for (int z = 0; z < last.z; ++z)
    for (int y = 0; y < last.y; ++y)
      for (int x = 0; x < last.x; ++x) {
        const glm::ivec3 c(x, y, z);
        const mc::Case& k = mc::caseTable()[f.cellCase(c)];
        for (int t = 0; t < k.triangles; ++t)
          mesh.triangles.emplace_back(vertexOn(c, k.edges[3 * t]), vertexOn(c, k.edges[3 * t + 1]),
                                      vertexOn(c, k.edges[3 * t + 2]));
      }
  return mesh;
}

}  // namespace tidepool
