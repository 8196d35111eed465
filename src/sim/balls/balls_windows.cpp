// The windows of the collide and statistics passes when the balls' vec4 arrays pass one storage
// block (gl/window.h). The balls are in cell order, so a window of them covers a run of cells
// [c0, c1], and every ball they can touch lies in the cells from c0 - reach to c1 + reach, where
// reach (a plane, a row and a cell) is the farthest of the 27 cells around a ball in the grid's
// numbering: the window of inputs runs from cellStart[c0 - reach] to cellStart[c1 + reach + 1].
// balls/reach_windows.comp finds those bounds on the GPU after the scan; the collide reads them
// back, one read per step. When some window's inputs would pass the limit, all windows are halved
// and planned again.
#include <algorithm>

#include "balls/bindings.glsl"
#include "base/error.h"
#include "sim/balls/balls.h"

namespace tidepool::balls {
namespace {
constexpr std::size_t kVec4 = sizeof(glm::vec4);

// Half a storage block of balls per window leaves the other half to the cells around them.
std::size_t firstWindowSize() {
  return std::max(gl::kWindowGrain, gl::windowElements(kVec4) / 2 / gl::kWindowGrain * gl::kWindowGrain);
}
bool windowed(std::size_t count) { return gl::needsWindows(count, kVec4); }
}  // namespace

void Balls::planReachWindows(std::size_t windowSize) {
  m_reachSize = 0;
  if (!windowed(m_count)) return;
  if (windowSize == 0) windowSize = firstWindowSize();
  const std::size_t windows = (m_count + windowSize - 1) / windowSize;
  if (m_reachBounds.size() < windows * sizeof(glm::uvec2)) m_reachBounds = gl::Buffer(windows * sizeof(glm::uvec2));
  const glm::uvec3 dims = m_grid->dims();
  const gl::Kernel<ReachUniforms> plan(m_shaders, "balls/reach_windows.comp", {BALLS_CELL_START, BALLS_REACH_BOUNDS});
  m_grid->cellStart().bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_CELL_START);
  m_reachBounds.bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_REACH_BOUNDS);
  plan.dispatchThreads(windows, {.windows = GLuint(windows),
                                 .windowSize = GLuint(windowSize),
                                 .count = GLuint(m_count),
                                 .cells = GLuint(m_grid->cells()),
                                 .reach = GLuint(dims.x * dims.y + dims.x + 1)});
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  m_reachSize = windowSize;
  m_reachCount = m_count;
}

std::vector<Balls::ReachWindow> Balls::reachWindows() {
  if (!windowed(m_count)) return {{{0, m_count}, {0, m_count}}};
  const std::size_t limit = gl::windowElements(kVec4);
  if (m_reachSize == 0 || m_reachCount != m_count) planReachWindows();
  for (;;) {
    const std::size_t size = m_reachSize, windows = (m_count + size - 1) / size;
    const std::vector<glm::uvec2> bounds = m_reachBounds.read<glm::uvec2>(windows);
    std::vector<ReachWindow> out;
    std::size_t widest = 0;
    for (std::size_t k = 0; k < windows; ++k) {
      const gl::Window balls{k * size, std::min(size, m_count - k * size)};
      const gl::Window sources = gl::alignedWindow(std::min<std::size_t>(bounds[k].x, balls.first),
                                                   std::max<std::size_t>(bounds[k].y, balls.end()), kVec4);
      widest = std::max(widest, sources.count);
      out.push_back({balls, sources});
    }
    if (widest <= limit) {
      m_reachSize = 0;  // used: the next grid plans again
      return out;
    }
    if (size <= gl::kWindowGrain)
      throw Error("balls: " + std::to_string(widest) + " balls lie within reach of a window of " +
                  std::to_string(size) + " (two planes of the grid's cells), over the storage-block limit of " +
                  std::to_string(limit) + " balls (" + gl::sizeText(gl::storageBlockBytes()) +
                  " per array): raise particles.radius or narrow the domain in x and y");
    planReachWindows(std::max(gl::kWindowGrain, size / 2 / gl::kWindowGrain * gl::kWindowGrain));
  }
}

}  // namespace tidepool::balls
