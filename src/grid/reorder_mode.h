// How UniformGrid::reorder() moves the particle arrays into cell order (src/grid/grid.h). Kept
// apart from grid.h so parameter structs (balls::Params) can name it without the GL headers.
//   scatter  one pass: particle i writes its elements to slot = cellStart[cell] + indexInCell[i]
//            (reads coalesced, writes to random slots: partial-sector writes when the order is random)
//   gather   two passes: permutation[slot] = i (4-byte scatter), then every slot reads
//            src[permutation[slot]] and writes dst[slot] (writes coalesced, reads random)
// Both give the same arrays and permutation for the same build (both place by indexInCell).
#pragma once

#include <array>

namespace tidepool::grid {

enum class ReorderMode { Scatter, Gather };
constexpr std::array<const char*, 2> kReorderModeNames = {"scatter", "gather"};

}  // namespace tidepool::grid
