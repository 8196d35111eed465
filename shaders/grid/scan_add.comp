#version 430 core
// Uniform add of the scan-then-propagate prefix sum (see src/grid/prefix_scan.h): adds each
// block's offset (its scanned block sum) to every element of the block, and the last block's
// offset to the total in out[uCount]. In place: in and out are bound to the same buffer.
#include "grid/scan_io.glsl"

void main() {
  uint block;
  bool partial;
  if (!groupBlock(block, partial)) return;
  const uint offset = blockSums[block];
  for (uint k = 0u; k < VECS; ++k) storeChunk(block, k, partial, loadChunk(block, k, partial) + offset);
  if (gl_LocalInvocationID.x == 0u && block + 1u == blockCount()) outWord[uCount] = inWord[uCount] + offset;
}
