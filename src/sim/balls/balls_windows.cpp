// The windows of the collide and statistics passes when the balls' vec4 arrays pass one storage
// block (gl/window.h). The balls are in cell order, so a window of them covers a run of cells
// [c0, c1], and every ball they can touch lies in the cells from c0 - reach to c1 + reach, where
// reach (a plane, a row and a cell) is the farthest of the 27 cells around a ball in the grid's
// numbering: the window of inputs runs from cellStart[c0 - reach] to cellStart[c1 + reach + 1].
// A window whose inputs would pass the limit is halved until they fit.
#include <algorithm>

#include "base/error.h"
#include "sim/balls/balls.h"

namespace tidepool::balls {

std::vector<Balls::ReachWindow> Balls::reachWindows(const gl::Buffer& sortedPositions) const {
  constexpr std::size_t kVec4 = sizeof(glm::vec4);
  if (!gl::needsWindows(m_count, kVec4)) return {{{0, m_count}, {0, m_count}}};
  const std::size_t limit = gl::windowElements(kVec4);
  const grid::reference::GridShape& shape = m_grid->shape();
  const std::size_t reach = std::size_t(shape.dims.x) * shape.dims.y + shape.dims.x + 1;
  const std::size_t cells = m_grid->cells();
  // Half a block of balls per window leaves the other half to the cells around them.
  const std::size_t half = std::max(gl::kWindowGrain, limit / 2 / gl::kWindowGrain * gl::kWindowGrain);
  std::vector<gl::Window> todo;
  for (std::size_t first = 0; first < m_count; first += half) todo.push_back({first, std::min(half, m_count - first)});
  std::reverse(todo.begin(), todo.end());
  std::vector<ReachWindow> out;
  while (!todo.empty()) {
    const gl::Window w = todo.back();
    todo.pop_back();
    const glm::vec4 a = sortedPositions.read<glm::vec4>(1, w.first)[0];
    const glm::vec4 b = sortedPositions.read<glm::vec4>(1, w.end() - 1)[0];
    const std::size_t c0 = grid::reference::cellOf(shape, glm::vec3(a));
    const std::size_t c1 = grid::reference::cellOf(shape, glm::vec3(b));
    const std::size_t lo = c0 > reach ? c0 - reach : 0, hi = std::min(c1 + reach + 1, cells);
    const std::size_t from = m_grid->cellStart().read<GLuint>(1, lo)[0];
    const std::size_t to = m_grid->cellStart().read<GLuint>(1, hi)[0];
    const gl::Window sources = gl::alignedWindow(std::min(from, w.first), std::max(to, w.end()), kVec4);
    if (sources.count <= limit) {
      out.push_back({w, sources});
      continue;
    }
    if (w.count <= gl::kWindowGrain)
      throw Error("balls: the " + std::to_string(sources.count) + " balls within reach of balls " +
                  std::to_string(w.first) + ".." + std::to_string(w.end() - 1) +
                  " (two planes of the grid's cells) pass the storage-block limit of " + std::to_string(limit) +
                  " balls (" + gl::sizeText(gl::storageBlockBytes()) +
                  " per array): raise particles.radius or narrow the domain in x and y");
    const std::size_t split = (w.count / 2 + gl::kWindowGrain - 1) / gl::kWindowGrain * gl::kWindowGrain;
    todo.push_back({w.first + split, w.count - split});
    todo.push_back({w.first, split});
  }
  return out;
}

}  // namespace tidepool::balls
