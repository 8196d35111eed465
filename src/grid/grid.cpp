#include "grid/grid.h"

#include <cmath>
#include <string>

#include "base/error.h"
#include "gl/window.h"

namespace tidepool::grid {
namespace {
constexpr std::size_t kWord = sizeof(uint32_t);

std::string vecText(glm::vec3 v) {
  return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

reference::GridShape shapeOf(const GridParams& p) {
  if (!(p.cellSize > 0.0f) || !std::isfinite(p.cellSize))
    throw Error("grid cell size must be a positive number, got " + std::to_string(p.cellSize));
  const glm::vec3 extent = p.domainMax - p.domainMin;
  if (!(extent.x > 0.0f) || !(extent.y > 0.0f) || !(extent.z >= 0.0f) || !std::isfinite(extent.x) ||
      !std::isfinite(extent.y) || !std::isfinite(extent.z))
    throw Error("grid domain max " + vecText(p.domainMax) + " must exceed min " + vecText(p.domainMin) +
                " in x and y (z may be equal, for a 2D grid)");
  double dims[3], cells = 1;
  for (int a = 0; a < 3; ++a) {
    dims[a] = std::max(1.0, std::ceil(double(extent[a]) / double(p.cellSize)));
    cells *= dims[a];
  }
  if (cells > double(UniformGrid::kMaxCells))
    throw Error("grid of " + std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " x " +
                std::to_string(dims[2]) + " cells is too many (at most 2^30): use a larger cell size than " +
                std::to_string(p.cellSize));
  if (p.layout == Layout::Half2 && extent.z != 0.0f)
    throw Error("grid: half-float positions (Layout::Half2) are 2D, but the domain's z extent is " +
                std::to_string(extent.z));
  reference::GridShape s;
  s.origin = p.domainMin;
  s.invCellSize = 1.0f / p.cellSize;
  s.dims = glm::uvec3(uint32_t(dims[0]), uint32_t(dims[1]), uint32_t(dims[2]));
  return s;
}

const char* halfDefine(const GridParams& p) { return p.layout == Layout::Half2 ? "1" : "0"; }

// The reorder and rank passes' storage blocks: every binding of grid/bindings.glsl.
constexpr std::initializer_list<GLuint> kReorderBindings = {
    GRID_PARTICLE_CELL, GRID_INDEX_IN_CELL,   GRID_CELL_START,  GRID_PERMUTATION,
    GRID_REORDER_SRC,   GRID_REORDER_SRC + 1, GRID_REORDER_DST, GRID_REORDER_DST + 1};

void checkArray(const gl::Buffer* b, std::size_t bytes, const std::string& what) {
  if (!b || b->size() < bytes)
    throw Error("grid: " + what + " needs " + std::to_string(bytes) + " bytes, the buffer " +
                (b ? "holds " + std::to_string(b->size()) : std::string("is missing")));
}
}  // namespace

UniformGrid::UniformGrid(gl::ShaderLibrary& shaders, const GridParams& params, std::size_t particleCapacity)
    : m_params(params),
      m_shape(shapeOf(params)),
      m_shaders(&shaders),
      m_maxBlockBytes(gl::storageBlockBytes()),
      m_ops(shaders),
      m_countPass(shaders, "grid/grid_count.comp",
                  {GRID_CELL_COUNT, GRID_INDEX_IN_CELL, GRID_PARTICLE_CELL_OUT, GRID_POSITIONS},
                  {{"HALF_POSITIONS", halfDefine(params)}}),
      m_scan(shaders) {
  const std::size_t startBytes = (cells() + 1) * kWord;
  if (startBytes > m_maxBlockBytes)
    throw Error("grid of " + std::to_string(cells()) + " cells needs " + gl::sizeText(startBytes) +
                " per cell array, over this driver's SSBO limit of " + gl::sizeText(m_maxBlockBytes) +
                ": use a larger cell size");
  m_cellCount = gl::Buffer(cells() * kWord);
  m_cellStart = gl::Buffer(startBytes);
  m_scan.reserve(cells());
  if (particleCapacity) m_indexInCell = gl::Buffer(particleCapacity * kWord);
  if (particleCapacity) m_particleCell = gl::Buffer(particleCapacity * kWord);
  if (particleCapacity && params.stable) m_members = gl::Buffer(particleCapacity * kWord);
}

void UniformGrid::build(const gl::Buffer& positions, std::size_t count) {
  countParticles(positions, count);
  scanCells();
}

void UniformGrid::prepareCount(std::size_t count) {
  // The particle arrays move a window at a time (gl/window.h); the per-particle words are bound whole.
  const std::size_t bytes = count * kWord;
  if (bytes > m_maxBlockBytes)
    throw Error("grid: " + std::to_string(count) + " particles need " + gl::sizeText(bytes) +
                " per array of 4-byte words, over this driver's SSBO limit of " + gl::sizeText(m_maxBlockBytes));
  if (m_indexInCell.size() < count * kWord) m_indexInCell = gl::Buffer(count * kWord);
  if (m_particleCell.size() < count * kWord) m_particleCell = gl::Buffer(count * kWord);
  m_count = count;
  // The previous count pass and scan read and wrote cellCount; their barriers order the clear.
  m_ops.fill(m_cellCount, 0);
}

void UniformGrid::countParticles(const gl::Buffer& positions, std::size_t count) {
  checkArray(&positions, count * elementBytes(), std::to_string(count) + " positions");
  prepareCount(count);
  if (count) {
    m_cellCount.bindBase(GL_SHADER_STORAGE_BUFFER, GRID_CELL_COUNT);
    m_indexInCell.bindBase(GL_SHADER_STORAGE_BUFFER, GRID_INDEX_IN_CELL);
    m_particleCell.bindBase(GL_SHADER_STORAGE_BUFFER, GRID_PARTICLE_CELL_OUT);
    for (const gl::Window& w : gl::windows(count, elementBytes())) {
      gl::bindWindow(positions, GRID_POSITIONS, w, elementBytes());
      m_countPass.dispatchThreads(w.count, {uniforms(), GLuint(w.first), GLuint(w.end())});
    }
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void UniformGrid::scanCells() { m_scan.run(m_cellCount, m_cellStart, cells()); }

void UniformGrid::reorder(const gl::Buffer& positions, std::span<const ReorderArray> arrays, gl::Buffer* permutation) {
  const std::size_t n = m_count;
  const std::size_t bytes = n * elementBytes();
  checkArray(&positions, bytes, "reorder: " + std::to_string(n) + " positions");
  for (std::size_t a = 0; a < arrays.size(); ++a) {
    checkArray(arrays[a].src, bytes, "reorder: source array " + std::to_string(a));
    checkArray(arrays[a].dst, bytes, "reorder: destination array " + std::to_string(a));
    if (arrays[a].src->id() == arrays[a].dst->id())
      throw Error("grid: reorder array " + std::to_string(a) + " has the same source and destination buffer");
  }
  if (permutation) checkArray(permutation, n * kWord, "reorder: permutation");
  if (!n || (arrays.empty() && !permutation)) return;
  m_particleCell.bindBase(GL_SHADER_STORAGE_BUFFER,
                          GRID_PARTICLE_CELL);  // the passes read the cells, not the positions
  m_indexInCell.bindBase(GL_SHADER_STORAGE_BUFFER, GRID_INDEX_IN_CELL);
  m_cellStart.bindBase(GL_SHADER_STORAGE_BUFFER, GRID_CELL_START);
  if (m_params.stable && !arrays.empty() && arrays[0].src->id() == positions.id() &&
      !gl::needsWindows(n, elementBytes())) {  // its positions and members share a binding
    rankAndScatter(arrays, permutation);
  } else {
    if (m_params.stable) rankWithinCells();
    scatter(arrays, permutation);
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

const gl::Kernel<UniformGrid::ReorderUniforms>& UniformGrid::reorderPass(std::size_t arrays, bool writePermutation) {
  gl::Kernel<ReorderUniforms>& kernel = m_reorderPass[arrays][writePermutation];
  if (!kernel.built())
    kernel = {*m_shaders,
              "grid/grid_reorder.comp",
              kReorderBindings,
              {{"ARRAYS", std::to_string(arrays)},
               {"WRITE_PERMUTATION", writePermutation ? "1" : "0"},
               {"HALF_POSITIONS", halfDefine(m_params)}}};
  return kernel;
}

// Binds the batch of up to GRID_REORDER_MAX_ARRAYS arrays starting at `first`; returns its size.
// Windows of src and dst (gl/window.h): all of each array when it fits one storage block.
std::size_t UniformGrid::bindBatch(std::span<const ReorderArray> arrays, std::size_t first, const gl::Window& src,
                                   const gl::Window& dst) const {
  const std::size_t batch = std::min<std::size_t>(GRID_REORDER_MAX_ARRAYS, arrays.size() - first);
  for (std::size_t a = 0; a < batch; ++a) {
    gl::bindWindow(*arrays[first + a].src, GLuint(GRID_REORDER_SRC + a), src, elementBytes());
    gl::bindWindow(*arrays[first + a].dst, GLuint(GRID_REORDER_DST + a), dst, elementBytes());
  }
  return batch;
}

// Batches of GRID_REORDER_MAX_ARRAYS arrays from `first` on; the first batch also writes the
// permutation.
void UniformGrid::scatter(std::span<const ReorderArray> arrays, gl::Buffer* permutation, std::size_t first) {
  if (permutation) permutation->bindBase(GL_SHADER_STORAGE_BUFFER, GRID_PERMUTATION);
  bool writePermutation = permutation != nullptr;
  const std::vector<gl::Window> windows = gl::windows(m_count, elementBytes());
  do {
    std::size_t batch = 0;
    for (const gl::Window& src : windows)  // each slot lies in one destination window
      for (const gl::Window& dst : windows) {
        batch = bindBatch(arrays, first, src, dst);
        reorderPass(batch, writePermutation)
            .dispatchThreads(src.count, {GLuint(src.first), GLuint(src.end()), GLuint(dst.first), GLuint(dst.count)});
      }
    first += batch;
    writePermutation = false;
  } while (first < arrays.size());
}

// The members pass is the scatter of the particle index into m_members; the rank pass then gives
// each particle its rank among them, into indexInCell for the scatter.
void UniformGrid::rankWithinCells() {
  writeMembers();
  m_members.bindBase(GL_SHADER_STORAGE_BUFFER, GRID_MEMBERS);
  rank(0, false, false);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}
// The members pass: the scatter of each particle's index into its cell, in atomic order.
void UniformGrid::writeMembers() {
  if (m_members.size() < m_count * kWord) m_members = gl::Buffer(m_count * kWord);
  m_members.bindBase(GL_SHADER_STORAGE_BUFFER, GRID_PERMUTATION);
  const GLuint n = GLuint(m_count);
  reorderPass(0, true).dispatchThreads(m_count, {0u, n, 0u, n});
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void UniformGrid::rank(std::size_t arrays, bool writePermutation, bool keepRank) {
  gl::Kernel<RankUniforms>& kernel = m_rankPass[arrays][writePermutation][keepRank];
  if (!kernel.built())
    kernel = {*m_shaders,
              "grid/grid_rank.comp",
              kReorderBindings,
              {{"ARRAYS", std::to_string(arrays)},
               {"WRITE_PERMUTATION", writePermutation ? "1" : "0"},
               {"KEEP_RANK", keepRank ? "1" : "0"},
               {"HALF_POSITIONS", halfDefine(m_params)}}};
  kernel.dispatchThreads(m_count, {uniforms(), GLuint(m_count)});
}

// The stable scatter when the positions are the first array: the members pass, then one pass
// that ranks each particle and moves the first batch of arrays to its slot (the positions read
// from that batch, the members bound in their place); later batches scatter by the rank it kept.
void UniformGrid::rankAndScatter(std::span<const ReorderArray> arrays, gl::Buffer* permutation) {
  writeMembers();
  const gl::Window all{0, m_count};
  const std::size_t batch = bindBatch(arrays, 0, all, all);
  const bool more = batch < arrays.size();
  m_members.bindBase(GL_SHADER_STORAGE_BUFFER, GRID_POSITIONS);
  if (permutation) permutation->bindBase(GL_SHADER_STORAGE_BUFFER, GRID_PERMUTATION);
  rank(batch, permutation != nullptr, more);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  if (!more) return;
  m_particleCell.bindBase(GL_SHADER_STORAGE_BUFFER, GRID_PARTICLE_CELL);
  scatter(arrays, nullptr, batch);
}

std::size_t UniformGrid::memoryBytes() const {
  return m_cellCount.size() + m_cellStart.size() + m_indexInCell.size() + m_particleCell.size() + m_members.size() +
         m_scan.memoryBytes();
}

}  // namespace tidepool::grid
