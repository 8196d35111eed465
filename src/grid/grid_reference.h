// Plain CPU versions of the grid passes: the oracle the GPU results are compared against in
// tests/grid, and the shortest statement of the method. cellOf() must stay bit-identical to
// shaders/common/grid.glsl (same float operations in the same order).
#pragma once

#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace tidepool::grid::reference {

struct GridShape {
  glm::vec3 origin{0.0f};    // domain min corner (world units)
  float invCellSize = 1.0f;  // 1 / cell size (1 / world units)
  glm::uvec3 dims{1u};       // cells per axis; z = 1 for a 2D grid
  std::size_t cells() const { return std::size_t(dims.x) * dims.y * dims.z; }
};

// Cell coordinate along one axis, clamped into [0, dims - 1] (NaN lands in cell 0).
inline uint32_t axisCell(float p, float origin, float invCellSize, uint32_t dims) {
  const float f = std::floor((p - origin) * invCellSize);
  const float last = float(dims - 1);
  if (!(f >= 0.0f)) return 0;
  return f >= last ? dims - 1 : uint32_t(f);
}

inline uint32_t cellOf(const GridShape& g, glm::vec3 p) {
  const uint32_t x = axisCell(p.x, g.origin.x, g.invCellSize, g.dims.x);
  const uint32_t y = axisCell(p.y, g.origin.y, g.invCellSize, g.dims.y);
  const uint32_t z = axisCell(p.z, g.origin.z, g.invCellSize, g.dims.z);
  return x + g.dims.x * (y + g.dims.y * z);
}

// Particles per cell.
inline std::vector<uint32_t> histogram(const GridShape& g, std::span<const glm::vec4> positions) {
  std::vector<uint32_t> counts(g.cells(), 0u);
  for (const glm::vec4& p : positions) ++counts[cellOf(g, glm::vec3(p))];
  return counts;
}

// Exclusive prefix sum with one extra entry holding the total: {2,0,3,1} -> {0,2,2,5,6}.
inline std::vector<uint32_t> exclusiveScan(std::span<const uint32_t> values) {
  std::vector<uint32_t> out(values.size() + 1);
  uint32_t sum = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    out[i] = sum;
    sum += values[i];
  }
  out[values.size()] = sum;
  return out;
}

// The stable grid's order (GridParams::stable): slot -> particle index, cells in index order and
// each cell's particles by index, a stable counting sort.
inline std::vector<uint32_t> stableOrder(const GridShape& g, std::span<const glm::vec4> positions) {
  const std::vector<uint32_t> counts = histogram(g, positions);
  std::vector<uint32_t> next = exclusiveScan(counts), order(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) order[next[cellOf(g, glm::vec3(positions[i]))]++] = uint32_t(i);
  return order;
}

}  // namespace tidepool::grid::reference
