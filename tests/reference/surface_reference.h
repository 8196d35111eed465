// CPU twins of the water-surface kernels (shaders/surface/*.comp), plain loops in the same order
// and the same float arithmetic: the reference the GPU mesh is compared against, and the plainest
// statement of the method (render/surface_mesher.h describes it).
//
//   const SurfaceGrid g = surfaceGrid(input, params, SIZE_MAX);
//   const std::vector<std::uint32_t> density = splatReference(positions, g);
//   const io::TriangleMesh mesh = marchReference(density, g, params.iso);
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "io/obj.h"
#include "render/surface_mesher.h"

namespace tidepool {

// splat.comp: fixed-point density per corner (SURFACE_FIXED_ONE per 1), shell corners left at 0.
std::vector<std::uint32_t> splatReference(const std::vector<glm::vec4>& positions, const SurfaceGrid& grid);
// classify + scan + emit: the welded mesh with normals, vertices in corner order (+x, +y, +z
// edges of each corner), triangles in cell order, as the GPU writes them.
io::TriangleMesh marchReference(const std::vector<std::uint32_t>& density, const SurfaceGrid& grid, float iso);

}  // namespace tidepool
