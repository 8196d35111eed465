// Grid cells debug view of the balls renderer (water-webgpu's "Grid cells"): the neighbour
// grid's non-empty cells drawn as wireframe cubes over the picture, coloured by how many balls
// each holds or all alike. Nothing comes back to the CPU: the cells are compacted on the GPU and
// drawn with one glDrawArraysIndirect whose instance count the compaction wrote.
//
//   cellCount   = {2, 0, 3, 1, 0}      the grid's counts (grid/grid.h)
//   flag        = {1, 0, 1, 1, 0}      grid_cells_flag.comp
//   scan        = {0, 1, 1, 2, 3, 3}   PrefixScan in place: slot of each non-empty cell, total last
//   list        = {24, 3, 0, 0 | 0, 2, 3}   grid_cells_compact.comp: the DrawArraysIndirectCommand
//                                      (24 vertices, 3 instances) then the non-empty cell ids
//   draw        GL_LINES, instance k draws cell list[4 + k]'s 12 edges (grid_cells.vert)
//
// The cubes are drawn after the compose, with no depth test: an overlay of the whole grid.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "gl/shader_library.h"
#include "grid/grid.h"
#include "grid/prefix_scan.h"
#include "render/balls_view_params.h"
#include "render/target.h"

namespace tidepool {

class BallsGridCells {
 public:
  explicit BallsGridCells(gl::ShaderLibrary& shaders);
  // The non-empty cells of `grid` (its counts of the last build) into list(); no read-back.
  void compact(const grid::UniformGrid& grid);
  // The compacted cells' edges into the bound target, the grid's frame mapped by clipFromGrid.
  // Population colours by count (blue: one ball, red: fullCount or more); NonEmpty uses `color`.
  void draw(const grid::UniformGrid& grid, const glm::mat4& clipFromGrid, GridCellsMode mode, float fullCount,
            glm::vec3 color, RenderTarget& target);

  const gl::Buffer& list() const { return m_list; }  // 4 uints of indirect command, then cell ids
  // Tests (blocking): the command's instance count and the ids it covers.
  std::uint32_t drawnCells() const;
  std::vector<std::uint32_t> cellIds() const;

 private:
  static constexpr std::size_t kHeaderUints = 4;  // DrawArraysIndirectCommand
  gl::ShaderLibrary& m_shaders;
  grid::PrefixScan m_scan;
  gl::Buffer m_flags;  // cells + 1 uints: flags, then their scan
  gl::Buffer m_list;   // kHeaderUints + cells uints
  gl::VertexArray m_vao = gl::VertexArray::create();
};

}  // namespace tidepool
