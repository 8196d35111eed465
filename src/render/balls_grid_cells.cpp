#include "render/balls_grid_cells.h"

#include "gl/kernel.h"
#include "render/balls/bindings.glsl"

namespace tidepool {
namespace {
struct CellsUniforms {
  GLuint cells = 0;  // of the grid
  static constexpr auto fields() { return std::tuple{gl::field("uCells", &CellsUniforms::cells)}; }
};
constexpr std::initializer_list<GLuint> kCellsBindings = {BALLS_VIEW_CELL_COUNT, BALLS_VIEW_CELL_SCAN,
                                                          BALLS_VIEW_CELL_LIST};
}  // namespace

BallsGridCells::BallsGridCells(gl::ShaderLibrary& shaders) : m_shaders(shaders), m_scan(shaders) {}

void BallsGridCells::compact(const grid::UniformGrid& grid) {
  const std::size_t cells = grid.cells();
  if (m_flags.size() < (cells + 1) * 4) m_flags.resize((cells + 1) * 4);
  if (m_list.size() < (kHeaderUints + cells) * 4) m_list.resize((kHeaderUints + cells) * 4);
  const gl::Kernel<CellsUniforms> flag(m_shaders, "render/balls/grid_cells_flag.comp", kCellsBindings);
  const gl::Kernel<CellsUniforms> compactPass(m_shaders, "render/balls/grid_cells_compact.comp", kCellsBindings);
  grid.cellCount().bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VIEW_CELL_COUNT);
  m_flags.bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VIEW_CELL_SCAN);
  flag.dispatchThreads(cells, {GLuint(cells)});
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  m_scan.run(m_flags, m_flags, cells);  // ends with its own storage barrier
  m_flags.bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VIEW_CELL_SCAN);
  m_list.bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VIEW_CELL_LIST);
  compactPass.dispatchThreads(cells, {GLuint(cells)});
  // The draw reads the command (indirect) and the ids (vertex shader storage).
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

void BallsGridCells::draw(const grid::UniformGrid& grid, const glm::mat4& clipFromGrid, GridCellsMode mode,
                          float fullCount, glm::vec3 color, RenderTarget& target) {
  if (mode == GridCellsMode::Hidden || !m_list) return;
  gl::Program& program = m_shaders.program({"render/balls/grid_cells.vert", "render/balls/grid_cells.frag"});
  program.use();
  program.set("uClipFromGrid", clipFromGrid);
  program.set("uOrigin", grid.params().domainMin);
  program.set("uCellSize", grid.params().cellSize);
  program.set("uDims", grid.dims());
  program.set("uByPopulation", mode == GridCellsMode::Population ? 1 : 0);
  program.set("uFullCount", fullCount);
  program.set("uColor", color);
  grid.cellCount().bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VIEW_CELL_COUNT);
  m_list.bindBase(GL_SHADER_STORAGE_BUFFER, BALLS_VIEW_CELL_LIST);
  target.bind();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  m_vao.bind();
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, m_list.id());
  glDrawArraysIndirect(GL_LINES, nullptr);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  glBindVertexArray(0);
  // Later readers of the target: read-backs, the window's blit, the next frame's compose image.
  glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

std::uint32_t BallsGridCells::drawnCells() const { return m_list ? m_list.read<std::uint32_t>(1, 1)[0] : 0; }

std::vector<std::uint32_t> BallsGridCells::cellIds() const {
  const std::uint32_t n = drawnCells();
  return n ? m_list.read<std::uint32_t>(n, kHeaderUints) : std::vector<std::uint32_t>{};
}

}  // namespace tidepool
