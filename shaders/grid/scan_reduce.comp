#version 430 core
// Reduce phase of the reduce-then-scan prefix sum (see src/grid/prefix_scan.h): the sum of each
// block of kScanBlock uints goes to blockSums[block]. Read-only over the input, so the level
// costs one read of N; the scan of the sums and the block scan with offsets follow.
#include "grid/scan_group.glsl"
#include "grid/scan_io.glsl"

void main() {
  uint block;
  bool partial;
  if (!groupBlock(block, partial)) return;
  uint sum = 0u;
  for (uint k = 0u; k < VECS; ++k) {
    const uvec4 v = loadChunk(block, k, partial);
    sum += v.x + v.y + v.z + v.w;
  }
  const uint total = groupSum(sum);
  if (gl_LocalInvocationID.x == 0u) blockSums[block] = total;
}
