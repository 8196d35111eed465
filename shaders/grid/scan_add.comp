#version 430 core
// Uniform add of the scan-then-propagate prefix sum (see src/grid/prefix_scan.h): adds each
// block's offset (its scanned block sum) to every element of the block, and the last block's
// offset to the total in out[uCount]. In place: in and out are bound to the same buffer.
layout(local_size_x = WG) in;
#include "common/index.glsl"
#include "grid/scan_io.glsl"

void main() {
  const uint block = groupIndex();
  if (block >= blockCount()) return;  // spare groups of a dispatch spilled into y (whole group)
  const bool partial = partialBlock(block);
  const uint offset = blockSums[block];
  for (uint k = 0u; k < VECS; ++k) storeChunk(block, k, partial, loadChunk(block, k, partial) + offset);
  if (gl_LocalInvocationID.x == 0u && block + 1u == blockCount()) outWord[uCount] = inWord[uCount] + offset;
}
