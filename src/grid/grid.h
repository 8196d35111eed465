// Uniform spatial grid on the GPU, shared by the balls, fluid and life models (and the fluid's density probe, the
// balls view's grid-cells overlay and the grid benchmark):
// particles are counted into cells, the counts are scanned into cell starts, and particle arrays
// are reordered so that each cell's particles are contiguous and cells are in index order (x
// fastest, then y, then z).
//
//   6 particles in 4 cells, cell of particle i = {2, 0, 2, 3, 2, 0}
//   count    cellCount   = {2, 0, 3, 1}        indexInCell = {0, 0, 1, 0, 2, 1}  (atomicAdd results)
//            particleCell = {2, 0, 2, 3, 2, 0}  (the reorder's passes read it, not the positions)
//   scan     cellStart   = {0, 2, 2, 5, 6}     exclusive prefix sum, last entry = particle total
//   reorder  slot        = cellStart[cell] + indexInCell = {2, 0, 3, 5, 4, 1}
//            dst         = {p1, p5, p0, p2, p4, p3}   cell c is dst[cellStart[c] .. cellStart[c + 1])
//            permutation = {1, 5, 0, 2, 4, 3}        permutation[slot] = original index (optional)
//
// The reorder is a scatter: particle i writes dst[slot] = src[i] (coalesced reads, random writes).
//
// Determinism (GridParams::stable, on by default): cellCount and cellStart are the same on every
// run, but the count pass's atomicAdd hands out the slots within a cell in scheduling order. A
// stable grid ranks each cell's particles by their index before the reorder, in two more passes:
//   members  members[cellStart[cell] + atomic slot] = i      (the cell's particles, any order)
//   rank     indexInCell[i] = #{ members of i's cell < i }   (the same on every run); when the
//            positions are the first array, the rank pass moves the arrays itself (one pass less)
//   cell 2 holds particles {0, 2, 4}; atomicAdd gave them slots {2, 0, 1} -> ranks {0, 1, 2}
// so the reordered arrays and the permutation are a stable counting sort: bit-identical runs for
// the models that sum over neighbours in grid order. A cell of more than GRID_STABLE_MAX_CELL
// particles (a blow-up piling into a border cell) keeps its atomic order rather than spend
// O(count^2) there. With stable = false the grid skips both passes (atomicAdd order).
// Arrays larger than one storage block (GL_MAX_SHADER_STORAGE_BLOCK_SIZE) move a window at a time
// (gl/window.h): the count pass one dispatch per window of positions, the scatter one per pair of
// source and destination windows (each kernel skips the particles whose other end
// lies outside its pair). The per-particle words (cells, ranks, members, permutation) and the cell
// arrays stay whole: they bound the particle count at the limit / 4 bytes.
// Positions are vec4 (xyz + w) std430 SSBOs, or for a 2D grid with Layout::Half2 uvec2 (x =
// packHalf2x16 of xy, y = any word), and then every reordered array has 8-byte elements. Positions outside the domain
// are clamped into the border cells (never dropped, never written out of bounds); a position exactly on a cell border
// belongs to the cell above it, one exactly on the domain max to the last cell. The cell math is
// shaders/common/grid.glsl (uniforms() feeds it to any kernel) and its CPU twin
// grid_reference.h. Every pass ends with GL_SHADER_STORAGE_BARRIER_BIT, so later kernels may read
// its output (Buffer::download adds its own read-back barrier); callers make their own writes to
// the positions visible the same way, and add GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT if they draw the
// reordered arrays as vertex attributes.
//
//   UniformGrid grid(shaders, {.domainMin = {0, 0, 0}, .domainMax = {4, 4, 4}, .cellSize = 0.5f});
//   grid.build(pos, n);                                    // count + scan
//   grid.reorder(pos, {{&pos, &posSorted}, {&vel, &velSorted}});
//   std::swap(pos, posSorted); std::swap(vel, velSorted);  // double-buffered, no copy back
#pragma once

#include <glm/glm.hpp>
#include <initializer_list>
#include <span>

#include "gl/buffer.h"
#include "gl/buffer_ops.h"
#include "gl/kernel.h"
#include "gl/window.h"
#include "grid/bindings.glsl"
#include "grid/grid_reference.h"
#include "grid/prefix_scan.h"

namespace tidepool::grid {

// What the grid reads and moves (shaders/grid/positions.glsl).
enum class Layout {
  Vec4,   // positions vec4 (xyz + w); reordered arrays of 16-byte elements
  Half2,  // 2D only: positions uvec2 (packHalf2x16(xy), any word); reordered arrays of 8-byte elements
};

struct GridParams {
  glm::vec3 domainMin{0.0f};  // world units
  glm::vec3 domainMax{1.0f};  // world units; z equal to domainMin.z makes a 2D grid (one layer)
  float cellSize = 0.1f;      // world units; at least the model's interaction radius
  Layout layout = Layout::Vec4;
  bool stable = true;  // order within a cell by particle index (see above)
};

// The cell math's uniforms (shaders/common/grid.glsl), a field of any kernel's uniform struct
// that includes it: gl::field(&MyUniforms::grid).
struct GridUniforms {
  glm::vec3 origin{0.0f};    // uGridOrigin, world units
  float invCellSize = 1.0f;  // uGridInvCellSize, 1 / world units
  glm::uvec3 dims{1u};       // uGridDims
  static constexpr auto fields() {
    return std::tuple{gl::field("uGridOrigin", &GridUniforms::origin),
                      gl::field("uGridInvCellSize", &GridUniforms::invCellSize),
                      gl::field("uGridDims", &GridUniforms::dims)};
  }
};

// One array to move by reorder(): src is read in particle order, dst written in cell order.
struct ReorderArray {
  const gl::Buffer* src;
  gl::Buffer* dst;
};

class UniformGrid {
 public:
  static constexpr std::size_t kMaxCells = std::size_t(1) << 30;  // cell indices stay in uint range

  // Dims per axis = ceil(extent / cellSize), at least 1. Throws Error for cellSize <= 0, max <= min
  // (max < min for z) or too many cells. particleCapacity only pre-allocates (build() grows).
  UniformGrid(gl::ShaderLibrary& shaders, const GridParams& params, std::size_t particleCapacity = 0);

  void build(const gl::Buffer& positions, std::size_t count);           // countParticles() + scanCells()
  void countParticles(const gl::Buffer& positions, std::size_t count);  // clear, atomicAdd pass
  void scanCells();                                                     // cellCount -> cellStart
  // For a kernel that counts the particles itself, as grid_count.comp does (atomicAdd into
  // cellCount(), the slot into indexInCell(), the cell into particleCell(), all bound by the
  // caller): checks the count against the limits, sizes those arrays, clears the counts.
  // scanCells() follows as after countParticles().
  void prepareCount(std::size_t count);
  // Moves each array to cell order for the positions and count of the last build (the positions
  // must be unchanged since). GRID_REORDER_MAX_ARRAYS arrays per dispatch; permutation optional.
  void reorder(const gl::Buffer& positions, std::span<const ReorderArray> arrays, gl::Buffer* permutation = nullptr);
  void reorder(const gl::Buffer& positions, std::initializer_list<ReorderArray> arrays,
               gl::Buffer* permutation = nullptr) {
    reorder(positions, std::span<const ReorderArray>(arrays.begin(), arrays.size()), permutation);
  }

  GridUniforms uniforms() const { return {m_shape.origin, m_shape.invCellSize, m_shape.dims}; }
  void setStable(bool stable) { m_params.stable = stable; }  // for the next reorder()

  const GridParams& params() const { return m_params; }
  const reference::GridShape& shape() const { return m_shape; }
  glm::uvec3 dims() const { return m_shape.dims; }
  bool is2D() const { return m_shape.dims.z == 1 && m_params.domainMax.z == m_params.domainMin.z; }
  std::size_t cells() const { return m_shape.cells(); }
  std::size_t particleCount() const { return m_count; }        // of the last build
  const gl::Buffer& cellCount() const { return m_cellCount; }  // uint per cell
  const gl::Buffer& cellStart() const { return m_cellStart; }  // uint per cell + 1 (total)
  const gl::Buffer& indexInCell() const {
    return m_indexInCell;
  }  // uint per particle (stable: the rank, after reorder)
  const gl::Buffer& particleCell() const { return m_particleCell; }  // uint per particle, its cell (count pass)
  std::size_t memoryBytes() const;  // all GPU buffers the grid owns, scan levels included
  std::size_t elementBytes() const { return m_params.layout == Layout::Half2 ? 8 : 16; }  // of positions and arrays

 private:
  GridParams m_params;
  reference::GridShape m_shape;
  gl::ShaderLibrary* m_shaders;
  std::size_t m_maxBlockBytes;  // GL_MAX_SHADER_STORAGE_BLOCK_SIZE, queried once
  gl::BufferOps m_ops;          // the cellCount clear
  struct CountUniforms {
    GridUniforms grid;
    GLuint first = 0, count = 0;  // the window's particles: [first, count)
    static constexpr auto fields() {
      return std::tuple{gl::field(&CountUniforms::grid), gl::field("uFirst", &CountUniforms::first),
                        gl::field("uCount", &CountUniforms::count)};
    }
  };
  struct ReorderUniforms {
    GLuint first = 0, count = 0;        // the source window's particles: [first, count)
    GLuint dstFirst = 0, dstCount = 0;  // the destination window: dstCount slots from dstFirst
    static constexpr auto fields() {
      return std::tuple{gl::field("uFirst", &ReorderUniforms::first), gl::field("uCount", &ReorderUniforms::count),
                        gl::field("uDstFirst", &ReorderUniforms::dstFirst),
                        gl::field("uDstCount", &ReorderUniforms::dstCount)};
    }
  };
  struct RankUniforms {
    GridUniforms grid;
    GLuint count = 0;  // particles
    static constexpr auto fields() {
      return std::tuple{gl::field(&RankUniforms::grid), gl::field("uCount", &RankUniforms::count)};
    }
  };
  gl::Kernel<CountUniforms> m_countPass;
  // Stable grid (grid_rank.comp) [arrays it moves][writes permutation][keeps the rank], made on use.
  gl::Kernel<RankUniforms> m_rankPass[GRID_REORDER_MAX_ARRAYS + 1][2][2] = {};
  gl::Kernel<ReorderUniforms> m_reorderPass[GRID_REORDER_MAX_ARRAYS + 1][2] = {};  // [arrays][writes permutation]
  PrefixScan m_scan;
  gl::Buffer m_cellCount, m_cellStart, m_indexInCell, m_particleCell;
  gl::Buffer m_members;  // stable grid: each cell's particles in atomic order, uint per particle

  const gl::Kernel<ReorderUniforms>& reorderPass(std::size_t arrays, bool writePermutation);
  std::size_t bindBatch(std::span<const ReorderArray> arrays, std::size_t first, const gl::Window& src,
                        const gl::Window& dst) const;
  void scatter(std::span<const ReorderArray> arrays, gl::Buffer* permutation, std::size_t first = 0);
  // Stable grid: the rank by index (see above) into indexInCell.
  void rankWithinCells();
  void writeMembers();
  void rank(std::size_t arrays, bool writePermutation, bool keepRank);  // the rank pass over all particles
  // Stable scatter with the positions as arrays[0]: the rank pass moves the first batch itself.
  void rankAndScatter(std::span<const ReorderArray> arrays, gl::Buffer* permutation);
  std::size_t m_count = 0;
};

}  // namespace tidepool::grid
