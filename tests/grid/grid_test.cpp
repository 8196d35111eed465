// The uniform grid against plain CPU loops: counts are a histogram, cellStart its exclusive scan,
// the reorder a permutation that makes cells contiguous and in order; 2D and 3D, particles on
// cell borders and outside the domain; counts and starts are the same on every run. Every batch
// of arrays and every window moves each element bit for bit to the slot the permutation names.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <glm/gtc/packing.hpp>
#include <random>
#include <regex>

#include "base/error.h"
#include "gl/buffer.h"
#include "gl/window.h"
#include "grid/grid.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::grid;

namespace {
class UniformGridTest : public test::GlTest {};

gl::Buffer vec4Buffer(const std::vector<glm::vec4>& v) {
  return gl::Buffer(std::max<std::size_t>(v.size(), 1) * sizeof(glm::vec4), v.data());
}

// Positions with w = particle id: uniform in the domain grown by `outside` on each side, plus
// points exactly on cell borders, on the domain's min and max, and far outside.
std::vector<glm::vec4> makePositions(const GridParams& p, std::size_t n, float outside, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<glm::vec4> out;
  const glm::vec3 lo = p.domainMin - outside, hi = p.domainMax + outside;
  const glm::vec3 cells = glm::ceil((p.domainMax - p.domainMin) / p.cellSize);
  for (std::size_t i = 0; i < n; ++i) {
    glm::vec3 x;
    switch (i % 8) {
      case 0:  // exactly on a cell border on every axis
        for (int a = 0; a < 3; ++a) x[a] = p.domainMin[a] + float(rng() % (int(cells[a]) + 1)) * p.cellSize;
        break;
      case 1: x = (i % 16 == 1) ? p.domainMin : p.domainMax; break;
      case 2: x = glm::vec3(1e30f, -1e30f, 1e6f) * (u(rng) < 0.5f ? 1.0f : -1.0f); break;
      default:
        for (int a = 0; a < 3; ++a) x[a] = lo[a] + (hi[a] - lo[a]) * u(rng);
    }
    if (p.domainMax.z == p.domainMin.z && i % 8 != 2) x.z = p.domainMin.z;
    out.emplace_back(x, float(i));
  }
  return out;
}

// The stable grid's permutation against the CPU's stable order, cell by cell: a cell of more than
// GRID_STABLE_MAX_CELL particles keeps its atomic order, so there only the members must agree.
void expectStableOrder(const std::vector<uint32_t>& got, const std::vector<uint32_t>& want,
                       const std::vector<uint32_t>& starts) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t cell = 0; cell + 1 < starts.size(); ++cell) {
    std::vector<uint32_t> a(got.begin() + starts[cell], got.begin() + starts[cell + 1]),
        b(want.begin() + starts[cell], want.begin() + starts[cell + 1]);
    if (a.size() > GRID_STABLE_MAX_CELL) std::sort(a.begin(), a.end());
    ASSERT_EQ(a, b) << "cell " << cell << " of " << a.size() << " particles";
  }
}

// Builds, reorders positions + two more arrays (two reorder batches) with the permutation, and
// checks everything against the CPU.
void checkGrid(gl::ShaderLibrary& shaders, const GridParams& params, const std::vector<glm::vec4>& pos) {
  const std::size_t n = pos.size();
  UniformGrid grid(shaders, params);
  const reference::GridShape& shape = grid.shape();
  std::vector<glm::vec4> vel(n), extra(n);
  for (std::size_t i = 0; i < n; ++i) {
    vel[i] = glm::vec4(float(i) * 2.0f, 1.0f, 2.0f, 3.0f);
    extra[i] = glm::vec4(-float(i), 0.5f, 0.25f, float(i % 7));
  }
  gl::Buffer posBuf = vec4Buffer(pos), velBuf = vec4Buffer(vel), extraBuf = vec4Buffer(extra);
  gl::Buffer posOut(posBuf.size()), velOut(velBuf.size()), extraOut(extraBuf.size()),
      perm(std::max<std::size_t>(n, 1) * 4);
  grid.build(posBuf, n);
  grid.reorder(posBuf, {{&posBuf, &posOut}, {&velBuf, &velOut}, {&extraBuf, &extraOut}}, &perm);

  const std::vector<uint32_t> counts = reference::histogram(shape, pos);
  const std::vector<uint32_t> starts = reference::exclusiveScan(counts);
  ASSERT_EQ(grid.cellCount().read<uint32_t>(grid.cells()), counts) << "counts must equal the CPU histogram";
  ASSERT_EQ(grid.cellStart().read<uint32_t>(grid.cells() + 1), starts);
  const std::vector<uint32_t> cellOfParticle = grid.particleCell().read<uint32_t>(n);
  for (std::size_t i = 0; i < n; ++i)
    ASSERT_EQ(cellOfParticle[i], reference::cellOf(shape, glm::vec3(pos[i]))) << "the stored cell of particle " << i;

  const std::vector<glm::vec4> sortedPos = posOut.read<glm::vec4>(n), sortedVel = velOut.read<glm::vec4>(n),
                               sortedExtra = extraOut.read<glm::vec4>(n);
  const std::vector<uint32_t> permutation = perm.read<uint32_t>(n);
  // Every particle exactly once: the ids (w) of the sorted positions are a permutation of 0..n-1.
  std::vector<uint32_t> ids(n);
  for (std::size_t j = 0; j < n; ++j) ids[j] = uint32_t(sortedPos[j].w);
  std::vector<uint32_t> sortedIds = ids;
  std::sort(sortedIds.begin(), sortedIds.end());
  for (std::size_t j = 0; j < n; ++j) ASSERT_EQ(sortedIds[j], j) << "particle ids lost or duplicated";
  // Cells contiguous and in cell order; all arrays moved together; the permutation names the source.
  std::size_t cell = 0;
  for (std::size_t j = 0; j < n; ++j) {
    while (starts[cell + 1] <= j) ++cell;
    const uint32_t i = ids[j];
    ASSERT_EQ(reference::cellOf(shape, glm::vec3(sortedPos[j])), cell) << "slot " << j << " (particle " << i << ")";
    ASSERT_EQ(permutation[j], i) << "slot " << j;
    ASSERT_EQ(sortedPos[j], pos[i]);
    ASSERT_EQ(sortedVel[j], vel[i]);
    ASSERT_EQ(sortedExtra[j], extra[i]);
  }
  // A stable grid is a stable counting sort: a cell's particles by index (but for crowded cells).
  if (params.stable) expectStableOrder(permutation, reference::stableOrder(shape, pos), starts);
  // indexInCell is a slot in the cell: distinct 0..count-1 per cell.
  const std::vector<uint32_t> slots = grid.indexInCell().read<uint32_t>(n);
  for (std::size_t i = 0; i < n; ++i)
    ASSERT_LT(slots[i], counts[reference::cellOf(shape, glm::vec3(pos[i]))]) << "particle " << i;
}

// Builds once, reorders `arrays` arrays (with or without the permutation), then the permutation
// alone from the same build, and checks that every element of every array landed bit for bit in
// the slot the permutation names, and that nothing past n was written.
void expectArraysFollowThePermutation(gl::ShaderLibrary& shaders, GridParams params, std::size_t n, int arrays,
                                      bool withPermutation, uint32_t seed) {
  SCOPED_TRACE("n " + std::to_string(n) + ", arrays " + std::to_string(arrays) +
               (withPermutation ? ", with permutation" : ", no permutation"));
  UniformGrid grid(shaders, params);
  const std::size_t words = grid.elementBytes() / 4, size = std::max<std::size_t>(n, 1) + 1;
  const std::vector<glm::vec4> wide = makePositions(params, n, 0.2f, seed);
  std::vector<std::vector<uint32_t>> values(std::max(arrays, 1), std::vector<uint32_t>(size * words, 0u));
  for (std::size_t i = 0; i < n; ++i) {  // array 0 (when there is one) is the positions
    if (params.layout == Layout::Half2) {
      values[0][2 * i] = glm::packHalf2x16(glm::vec2(wide[i]));
      values[0][2 * i + 1] = uint32_t(i);
    } else {
      std::memcpy(&values[0][4 * i], &wide[i], 16);
    }
  }
  std::mt19937 rng(seed);
  for (int a = 1; a < arrays; ++a)
    for (uint32_t& v : values[std::size_t(a)]) v = rng();  // any bit pattern, NaNs included
  const std::vector<uint32_t> fill(size * words, 0xaaaaaaaau);
  std::vector<gl::Buffer> src, dst;
  std::vector<ReorderArray> batch;
  for (int a = 0; a < std::max(arrays, 1); ++a)
    src.emplace_back(values[std::size_t(a)].size() * 4, values[std::size_t(a)].data());
  for (int a = 0; a < arrays; ++a) dst.emplace_back(fill.size() * 4, fill.data());
  for (int a = 0; a < arrays; ++a) batch.push_back({&src[std::size_t(a)], &dst[std::size_t(a)]});
  gl::Buffer given(size * 4, fill.data()), alone(size * 4, fill.data());
  grid.build(src[0], n);
  grid.reorder(src[0], batch, withPermutation ? &given : nullptr);
  grid.reorder(src[0], std::span<const ReorderArray>(), &alone);
  const std::vector<uint32_t> perm = alone.read<uint32_t>(n);
  if (withPermutation) ASSERT_EQ(given.read<uint32_t>(n), perm) << "the permutation depends on the arrays moved";
  std::vector<uint32_t> ids = perm;
  std::sort(ids.begin(), ids.end());
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(ids[i], i) << "not a permutation";
  for (int a = 0; a < arrays; ++a) {
    const std::vector<uint32_t> got = dst[std::size_t(a)].read<uint32_t>(size * words);
    const std::vector<uint32_t>& from = values[std::size_t(a)];
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t w = 0; w < words; ++w)
        ASSERT_EQ(got[j * words + w], from[perm[j] * words + w]) << "array " << a << ", slot " << j;
    for (std::size_t k = n * words; k < got.size(); ++k) ASSERT_EQ(got[k], 0xaaaaaaaau) << "written past n";
  }
}

// Sizes 0, 1, 2, one and two work groups (256) +-1 and random ones; 0..5 arrays (up to three
// dispatch batches), with and without the permutation.
void reorderSweep(gl::ShaderLibrary& shaders, const GridParams& params, uint32_t seed) {
  std::vector<std::size_t> sizes = {0, 1, 2, 255, 256, 257, 511, 512, 513};
  std::mt19937 rng(seed);
  for (int k = 0; k < 3; ++k) sizes.push_back(1 + rng() % 6000);
  for (std::size_t n : sizes)
    for (int arrays : {0, 1, 2, 3, 5})
      for (bool withPermutation : {false, true})
        expectArraysFollowThePermutation(shaders, params, n, arrays, withPermutation, seed + uint32_t(n));
}

// The count pass's atomic slots overwritten with the worst order scheduling could give: each
// cell's particles in reverse index order. On llvmpipe the slots mostly come out in index order
// already, so without this a rank that kept the atomic slots would pass.
void reverseSlots(const UniformGrid& grid, const std::vector<glm::vec4>& pos) {
  const std::vector<uint32_t> counts = reference::histogram(grid.shape(), pos);
  std::vector<uint32_t> taken(counts.size(), 0), slots(pos.size());
  for (std::size_t i = 0; i < pos.size(); ++i) {
    const uint32_t cell = reference::cellOf(grid.shape(), glm::vec3(pos[i]));
    slots[i] = counts[cell] - 1 - taken[cell]++;
  }
  glBindBuffer(GL_COPY_WRITE_BUFFER, grid.indexInCell().id());
  glBufferSubData(GL_COPY_WRITE_BUFFER, 0, GLsizeiptr(slots.size() * 4), slots.data());
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
}
}  // namespace

TEST_F(UniformGridTest, ExampleFromTheHeader) {
  UniformGrid grid(shaders(), {.domainMin = {0, 0, 0}, .domainMax = {4, 1, 0}, .cellSize = 1.0f});
  ASSERT_EQ(grid.dims(), glm::uvec3(4, 1, 1));
  EXPECT_TRUE(grid.is2D());
  const std::vector<glm::vec4> pos = {{2.5f, 0.5f, 0, 0}, {0.5f, 0.5f, 0, 1}, {2.5f, 0.5f, 0, 2},
                                      {3.5f, 0.5f, 0, 3}, {2.5f, 0.5f, 0, 4}, {0.5f, 0.5f, 0, 5}};
  gl::Buffer posBuf = vec4Buffer(pos), posOut(posBuf.size()), perm(6 * 4);
  grid.build(posBuf, pos.size());
  EXPECT_EQ(grid.cellCount().readAll<uint32_t>(), (std::vector<uint32_t>{2, 0, 3, 1}));
  EXPECT_EQ(grid.cellStart().readAll<uint32_t>(), (std::vector<uint32_t>{0, 2, 2, 5, 6}));
  grid.reorder(posBuf, {{&posBuf, &posOut}}, &perm);
  EXPECT_EQ(perm.readAll<uint32_t>(), (std::vector<uint32_t>{1, 5, 0, 2, 4, 3})) << "stable: by index in a cell";
}

TEST_F(UniformGridTest, Random3DWithBordersAndOutsiders) {
  const GridParams params{.domainMin = {-1, 0, 2}, .domainMax = {3, 2, 3.5f}, .cellSize = 0.25f};
  checkGrid(shaders(), params, makePositions(params, 20000, 0.5f, 1));
}

TEST_F(UniformGridTest, Random2DWithBordersAndOutsiders) {
  const GridParams params{.domainMin = {0, 0, 0}, .domainMax = {8, 4, 0}, .cellSize = 0.5f};
  checkGrid(shaders(), params, makePositions(params, 30001, 1.0f, 2));
}

TEST_F(UniformGridTest, ManyParticlesPerCellAndManyCells) {
  // ~8 per cell over more cells than one scan block (two-level scan), and a crowded tiny grid.
  const GridParams wide{.domainMin = {0, 0, 0}, .domainMax = {24, 24, 24}, .cellSize = 1.0f};
  checkGrid(shaders(), wide, makePositions(wide, 8 * 24 * 24 * 24, 0.0f, 3));
  const GridParams tiny{.domainMin = {0, 0, 0}, .domainMax = {1, 1, 1}, .cellSize = 0.5f};
  checkGrid(shaders(), tiny, makePositions(tiny, 5000, 0.1f, 4));
}

// Without the stable order the cells are the same and any order within a cell is allowed.
TEST_F(UniformGridTest, AtomicOrderWhenNotStable) {
  GridParams params{.domainMin = {-1, 0, 2}, .domainMax = {3, 2, 3.5f}, .cellSize = 0.25f};
  params.stable = false;
  checkGrid(shaders(), params, makePositions(params, 20000, 0.5f, 21));
}

// A cell of more than GRID_STABLE_MAX_CELL particles keeps its atomic order (still a valid
// reorder); the cells beside it are ranked as usual.
TEST_F(UniformGridTest, CrowdedCellKeepsAValidOrder) {
  const GridParams params{.domainMin = {0, 0, 0}, .domainMax = {4, 4, 4}, .cellSize = 1.0f};
  std::vector<glm::vec4> pos = makePositions(params, 6000, 0.0f, 22);
  for (std::size_t i = 0; i < 3000; i += 2) pos[i] = glm::vec4(0.5f, 0.5f, 0.5f, float(i));
  ASSERT_GT(reference::histogram(UniformGrid(shaders(), params).shape(), pos)[0], uint32_t(GRID_STABLE_MAX_CELL))
      << "cell 0 must be crowded";
  checkGrid(shaders(), params, pos);
}

TEST_F(UniformGridTest, NonMultipleCellSizeRoundsDimsUp) {
  UniformGrid grid(shaders(), {.domainMin = {0, 0, 0}, .domainMax = {1, 1, 1}, .cellSize = 0.3f});
  EXPECT_EQ(grid.dims(), glm::uvec3(4, 4, 4));
  EXPECT_FALSE(grid.is2D());
  const GridParams params = grid.params();
  checkGrid(shaders(), params, makePositions(params, 3000, 0.2f, 5));
}

// Layout::Half2 (particle life's fp16 state): positions are uvec2 (packHalf2x16(xy), a word) and
// the reordered arrays have 8-byte elements, moved bit for bit (NaN patterns included).
TEST_F(UniformGridTest, HalfFloatPositionsAndEightByteArrays) {
  const GridParams params = {
      .domainMin = {-8, -4, 0}, .domainMax = {8, 4, 0}, .cellSize = 0.75f, .layout = Layout::Half2};
  const std::vector<glm::vec4> wide = makePositions(params, 20001, 1.0f, 7);
  const std::size_t n = wide.size();
  std::vector<glm::uvec2> pos(n), other(n);
  std::vector<glm::vec4> rounded(n);  // what the grid sees
  for (std::size_t i = 0; i < n; ++i) {
    pos[i] = {glm::packHalf2x16(glm::vec2(wide[i])), uint32_t(i)};
    rounded[i] = glm::vec4(glm::unpackHalf2x16(pos[i].x), 0.0f, float(i));
    other[i] = {0x7fc00000u + uint32_t(i), ~uint32_t(i)};  // float NaN patterns
  }
  UniformGrid grid(shaders(), params);
  EXPECT_EQ(grid.elementBytes(), 8u);
  gl::Buffer posBuf(n * 8, pos.data()), otherBuf(n * 8, other.data()), posOut(n * 8), otherOut(n * 8), perm(n * 4);
  grid.build(posBuf, n);
  grid.reorder(posBuf, {{&posBuf, &posOut}, {&otherBuf, &otherOut}}, &perm);
  const std::vector<uint32_t> counts = reference::histogram(grid.shape(), rounded);
  const std::vector<uint32_t> starts = reference::exclusiveScan(counts);
  ASSERT_EQ(grid.cellCount().read<uint32_t>(grid.cells()), counts);
  ASSERT_EQ(grid.cellStart().read<uint32_t>(grid.cells() + 1), starts);
  const std::vector<uint32_t> cellOfParticle = grid.particleCell().read<uint32_t>(n);
  for (std::size_t i = 0; i < n; ++i)
    ASSERT_EQ(cellOfParticle[i], reference::cellOf(grid.shape(), glm::vec3(rounded[i])))
        << "the stored cell of particle " << i;
  const std::vector<glm::uvec2> sortedPos = posOut.read<glm::uvec2>(n), sortedOther = otherOut.read<glm::uvec2>(n);
  const std::vector<uint32_t> permutation = perm.read<uint32_t>(n);
  std::size_t cell = 0;
  for (std::size_t j = 0; j < n; ++j) {
    while (starts[cell + 1] <= j) ++cell;
    const uint32_t i = permutation[j];
    ASSERT_LT(i, n);
    ASSERT_EQ(reference::cellOf(grid.shape(), glm::vec3(rounded[i])), cell) << "slot " << j;
    ASSERT_EQ(sortedPos[j], pos[i]) << "slot " << j;
    ASSERT_EQ(sortedOther[j], other[i]) << "slot " << j;
  }
  EXPECT_THROW(UniformGrid(shaders(), {.domainMin = {0, 0, 0}, .domainMax = {1, 1, 1}, .layout = Layout::Half2}), Error)
      << "half positions are 2D";
  EXPECT_THROW(grid.build(posOut, n + 1), Error) << "n + 1 positions need 8 more bytes";
}

TEST_F(UniformGridTest, ZeroParticles) {
  UniformGrid grid(shaders(), {.domainMin = {0, 0, 0}, .domainMax = {2, 2, 2}, .cellSize = 1.0f});
  const glm::vec4 untouched(7.0f);
  gl::Buffer pos(16), out(16, &untouched), perm(4);
  grid.build(pos, 0);
  EXPECT_EQ(grid.cellStart().readAll<uint32_t>(), std::vector<uint32_t>(9, 0u));
  grid.reorder(pos, {{&pos, &out}}, &perm);
  EXPECT_EQ(grid.particleCount(), 0u);
  EXPECT_EQ(out.read<glm::vec4>(1)[0], untouched) << "nothing to move";
}

TEST_F(UniformGridTest, ArraysFollowThePermutation3D) {
  reorderSweep(shaders(), {.domainMin = {-1, 0, 2}, .domainMax = {3, 2, 3.5f}, .cellSize = 0.25f}, 11);
}

TEST_F(UniformGridTest, ArraysFollowThePermutation2D) {
  reorderSweep(shaders(), {.domainMin = {0, 0, 0}, .domainMax = {8, 4, 0}, .cellSize = 0.5f}, 12);
}

TEST_F(UniformGridTest, ArraysFollowThePermutationHalfFloat) {
  reorderSweep(shaders(),
               {.domainMin = {-8, -4, 0}, .domainMax = {8, 4, 0}, .cellSize = 0.75f, .layout = Layout::Half2}, 13);
}

// A reorder of the balls' kind (positions alone, no permutation) repeated from its own output (the
// last step's cell order).
TEST_F(UniformGridTest, ReorderFromCellOrderKeepsTheCells) {
  const GridParams params{.domainMin = {0, 0, 0}, .domainMax = {6, 6, 6}, .cellSize = 0.5f};
  const std::vector<glm::vec4> pos = makePositions(params, 7000, 0.1f, 14);
  UniformGrid grid(shaders(), params);
  gl::Buffer a = vec4Buffer(pos), b(a.size()), c(a.size());
  grid.build(a, pos.size());
  grid.reorder(a, {{&a, &b}});
  grid.build(b, pos.size());
  grid.reorder(b, {{&b, &c}});
  // Sorted input: every cell's particles are already together, so the rebuild keeps the cells;
  // inside a cell the atomicAdd order may shuffle them.
  const std::vector<glm::vec4> first = b.read<glm::vec4>(pos.size()), second = c.read<glm::vec4>(pos.size());
  const std::vector<uint32_t> starts = grid.cellStart().read<uint32_t>(grid.cells() + 1);
  for (std::size_t cell = 0; cell < grid.cells(); ++cell) {
    std::vector<float> x, y;
    for (uint32_t j = starts[cell]; j < starts[cell + 1]; ++j) {
      x.push_back(first[j].w);
      y.push_back(second[j].w);
    }
    std::sort(x.begin(), x.end());
    std::sort(y.begin(), y.end());
    ASSERT_EQ(x, y) << "cell " << cell;
  }
}

// Both rank paths (the rank pass moving the positions itself, and the rank alone before a
// scatter) give the stable counting sort from reversed slots; the atomic order keeps them reversed.
TEST_F(UniformGridTest, StableOrderDoesNotDependOnTheAtomicSlots) {
  GridParams params{.domainMin = {-1, 0, 2}, .domainMax = {3, 2, 3.5f}, .cellSize = 0.25f};
  const std::vector<glm::vec4> pos = makePositions(params, 6000, 0.5f, 31);
  const std::size_t n = pos.size();
  UniformGrid grid(shaders(), params);
  gl::Buffer posBuf = vec4Buffer(pos), posOut(posBuf.size()), velOut(posBuf.size()), perm(n * 4);
  gl::Buffer vel = vec4Buffer(std::vector<glm::vec4>(n, glm::vec4(1.0f)));
  grid.build(posBuf, n);
  const std::vector<uint32_t> starts = grid.cellStart().read<uint32_t>(grid.cells() + 1);
  const std::vector<uint32_t> want = reference::stableOrder(grid.shape(), pos);
  {
    SCOPED_TRACE("rank and scatter in one pass");
    reverseSlots(grid, pos);
    grid.reorder(posBuf, {{&posBuf, &posOut}}, &perm);
    expectStableOrder(perm.read<uint32_t>(n), want, starts);
  }
  {
    SCOPED_TRACE("rank, then the scatter");
    reverseSlots(grid, pos);
    grid.reorder(posBuf, {{&vel, &velOut}}, &perm);
    expectStableOrder(perm.read<uint32_t>(n), want, starts);
  }
  grid.setStable(false);
  reverseSlots(grid, pos);
  grid.reorder(posBuf, {{&posBuf, &posOut}}, &perm);
  const std::vector<uint32_t> atomic = perm.read<uint32_t>(n);
  std::size_t reversedCells = 0;
  for (std::size_t cell = 0; cell + 1 < starts.size(); ++cell)
    if (starts[cell + 1] - starts[cell] > 1)
      reversedCells += atomic[starts[cell]] == want[starts[cell + 1] - 1] ? 1 : 0;
  EXPECT_GT(reversedCells, 100u) << "the reversed slots must reach the reorder";
}

TEST_F(UniformGridTest, CountsAndStartsAreDeterministic) {
  const GridParams params{.domainMin = {0, 0, 0}, .domainMax = {10, 10, 10}, .cellSize = 0.5f};
  const std::vector<glm::vec4> pos = makePositions(params, 50000, 0.3f, 6);
  gl::Buffer posBuf = vec4Buffer(pos);
  std::vector<uint32_t> counts, starts;
  for (int run = 0; run < 3; ++run) {
    UniformGrid grid(shaders(), params);
    for (int rebuild = 0; rebuild < 2; ++rebuild) {
      grid.build(posBuf, pos.size());
      if (counts.empty()) {
        counts = grid.cellCount().readAll<uint32_t>();
        starts = grid.cellStart().readAll<uint32_t>();
      }
      EXPECT_EQ(grid.cellCount().readAll<uint32_t>(), counts);
      EXPECT_EQ(grid.cellStart().readAll<uint32_t>(), starts);
    }
  }
}

TEST_F(UniformGridTest, MemoryIsReported) {
  UniformGrid grid(shaders(), {.domainMin = {0, 0, 0}, .domainMax = {64, 64, 64}, .cellSize = 1.0f}, 1000);
  const std::size_t cells = 64 * 64 * 64;
  // counts + starts + indexInCell + particleCell + the stable order's members + scan levels (64 + 1 block sums)
  EXPECT_EQ(grid.memoryBytes(),
            cells * 4 + (cells + 1) * 4 + 3 * 1000 * 4 + (cells / PrefixScan::Config{}.block() + 1) * 4);
  UniformGrid atomic(shaders(), {.domainMin = {0, 0, 0}, .domainMax = {64, 64, 64}, .cellSize = 1.0f, .stable = false},
                     1000);
  EXPECT_EQ(atomic.memoryBytes(), grid.memoryBytes() - 1000 * 4);
}

TEST_F(UniformGridTest, BadInputThrowsOneLineErrors) {
  auto make = [&](GridParams p) { UniformGrid grid(shaders(), p); };
  const glm::vec3 zero(0.0f), one(1.0f);
  for (float cell : {0.0f, -1.0f, std::nanf("")})
    EXPECT_THROW(make({.domainMin = zero, .domainMax = one, .cellSize = cell}), Error) << cell;
  EXPECT_THROW(make({.domainMin = one, .domainMax = zero, .cellSize = 0.1f}), Error);
  EXPECT_THROW(make({.domainMin = zero, .domainMax = {1, 0, 1}, .cellSize = 0.1f}), Error);  // y extent 0
  EXPECT_THROW(make({.domainMin = zero, .domainMax = {1, 1, -1}, .cellSize = 0.1f}), Error);
  try {
    make({.domainMin = zero, .domainMax = glm::vec3(1e4f), .cellSize = 1e-2f});
    ADD_FAILURE() << "expected too many cells";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("larger cell size"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
  UniformGrid grid(shaders(), {.domainMin = zero, .domainMax = one, .cellSize = 0.5f});
  gl::Buffer small(16);
  EXPECT_THROW(grid.build(small, 2), Error);  // 2 positions need 32 bytes
  gl::Buffer pos(32), out(32);
  grid.build(pos, 2);
  EXPECT_THROW(grid.reorder(pos, {{&pos, &small}}), Error);
  EXPECT_THROW(grid.reorder(pos, {{&pos, &pos}}), Error);
  gl::Buffer shortPermutation(4);
  EXPECT_THROW(grid.reorder(pos, {{&pos, &out}}, &shortPermutation), Error);  // 2 particles need 8 bytes
}

TEST(GridBindings, HeaderHoldsOnlyDefinesSharedWithCpp) {
  // C++ and GLSL include the same file, so it must be valid in both: #define lines only.
  std::ifstream in(std::string(TIDEPOOL_SOURCE_DIR) + "/shaders/grid/bindings.glsl");
  ASSERT_TRUE(in);
  const std::regex define(R"(#define [A-Z_0-9]+ \d+( +//.*)?)");
  int lines = 0;
  for (std::string line; std::getline(in, line); ++lines) EXPECT_TRUE(std::regex_match(line, define)) << line;
  EXPECT_GT(lines, 0);
  EXPECT_LE(GRID_REORDER_DST + GRID_REORDER_MAX_ARRAYS, 8) << "GL 4.3 guarantees only 8 SSBO bindings";
}

// Arrays over one storage block (gl/window.h): with the smallest limit tidepool runs with, 64 KiB,
// windows hold 4096 vec4s (8192 half pairs), so these counts move in two to four windows per array
// and every pair of windows; the 4-byte words (16384 at most) stay whole. The results must be the
// unwindowed ones: the same CPU checks, every element where the permutation says.
namespace {
class WindowedGrid : public UniformGridTest {
 protected:
  void SetUp() override { gl::overrideStorageBlockBytes(gl::kMinStorageBlockBytes); }
  void TearDown() override { gl::overrideStorageBlockBytes(0); }
};
}  // namespace

TEST_F(WindowedGrid, ArraysMoveInWindows) {
  ASSERT_EQ(gl::windows(15000, 16).size(), 4u);
  for (bool stable : {true, false}) {
    SCOPED_TRACE(stable ? "stable" : "atomic order");
    GridParams params{.domainMin = {-1, 0, 2}, .domainMax = {3, 2, 3.5f}, .cellSize = 0.25f};
    params.stable = stable;
    checkGrid(shaders(), params, makePositions(params, 15000, 0.5f, 31));
  }
}

TEST_F(WindowedGrid, ArraysFollowThePermutationAcrossWindows) {
  const GridParams wide{.domainMin = {-1, 0, 2}, .domainMax = {3, 2, 3.5f}, .cellSize = 0.25f};
  for (std::size_t n : {4095, 4096, 4097, 8192, 12289, 16384})
    for (int arrays : {1, 3})
      for (bool withPermutation : {false, true})
        expectArraysFollowThePermutation(shaders(), wide, n, arrays, withPermutation, 40 + uint32_t(n));
  const GridParams half{.domainMin = {-8, -4, 0}, .domainMax = {8, 4, 0}, .cellSize = 0.75f, .layout = Layout::Half2};
  expectArraysFollowThePermutation(shaders(), half, 16000, 2, true, 41);
}

TEST_F(WindowedGrid, WordsOverOneBlockAreRefused) {
  const GridParams params{.domainMin = {0, 0, 0}, .domainMax = {1, 1, 1}, .cellSize = 0.25f};
  UniformGrid grid(shaders(), params);
  gl::Buffer pos(16385 * sizeof(glm::vec4));
  EXPECT_THROW(grid.build(pos, 16385), Error) << "16385 cells or ranks of 4 bytes pass 64 KiB";
}
