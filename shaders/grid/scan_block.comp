#version 430 core
// Block scan of the prefix sum (see src/grid/prefix_scan.h): each work group scans its block of
// kScanBlock uints in registers and shared memory and writes the exclusive prefix sums.
//   uOffsets = 1 (reduce-then-scan): adds blockSums[block], the block's offset from the
//                scanned sums of the level above, while storing (the uniform add, fused).
//   uOffsets = 2 (fused reduce-then-scan): the sums are scan_reduce's, unscanned; the group adds
//                up blockSums[0..block) itself (coalesced uvec4 loads and the shared-memory tree,
//                while its own block's loads are in flight) and adds that while storing.
// The last block also writes its total (plus its offset) to out[uCount].
#include "grid/scan_group.glsl"
#include "grid/scan_io.glsl"

layout(std430, binding = SCAN_BLOCK_SUMS_VEC) readonly buffer BlockSumsVec { uvec4 blockSumsVec[]; };

uniform uint uOffsets;  // 0: none, 1: blockSums[block] (scanned), 2: sum of blockSums[0..block)

shared uint sChunk[SCAN_PAD(WG * VECS)];  // per-chunk sums, then per-chunk prefixes, element order

// blockSums[0] + ... + blockSums[block - 1]: whole uvec4 first (the buffer is 16-byte aligned),
// then the last block % 4 words. The same for the whole group; call from uniform control flow.
uint sumOfEarlierBlocks(uint block) {
  const uint t = gl_LocalInvocationID.x;
  uint part = 0u;
  for (uint c = t; c < block / 4u; c += WG) {
    const uvec4 s = blockSumsVec[c];
    part += s.x + s.y + s.z + s.w;
  }
  if (t < block % 4u) part += blockSums[block - block % 4u + t];
  return groupSum(part);
}

void main() {
  uint block;
  bool partial;
  if (!groupBlock(block, partial)) return;
  const uint t = gl_LocalInvocationID.x;

  // 1. Exclusive scan inside each 4-element chunk; chunk sums go to shared memory. The block's
  // offset is read (or summed) between the loads and their first use.
  uvec4 v[VECS];
  for (uint k = 0u; k < VECS; ++k) v[k] = loadChunk(block, k, partial);
  uint offset = 0u;
  if (uOffsets == 2u)  // uniform: the whole dispatch takes this branch or none does
    offset = sumOfEarlierBlocks(block);
  else if (uOffsets == 1u)
    offset = blockSums[block];
  for (uint k = 0u; k < VECS; ++k) {
    const uvec4 x = v[k];
    v[k] = uvec4(0u, x.x, x.x + x.y, x.x + x.y + x.z);
    sChunk[SCAN_PAD(k * WG + t)] = v[k].w + x.w;
  }
  groupSync();

  // 2. Each invocation scans VECS consecutive chunk sums, the group scans the invocation totals.
  uint chunkPrefix[VECS];
  uint run = 0u;
  for (uint j = 0u; j < VECS; ++j) {
    chunkPrefix[j] = run;
    run += sChunk[SCAN_PAD(t * VECS + j)];
  }
  uint total;
  const uint before = groupExclusiveScan(run, total);
  for (uint j = 0u; j < VECS; ++j) sChunk[SCAN_PAD(t * VECS + j)] = before + chunkPrefix[j];
  groupSync();

  // 3. Add chunk prefix and block offset, store (coalesced, like the loads).
  for (uint k = 0u; k < VECS; ++k) storeChunk(block, k, partial, v[k] + (sChunk[SCAN_PAD(k * WG + t)] + offset));
  if (t == 0u) {
    // Never true (uCount <= 2^31), but with a store to blockSums that it cannot rule out, NVIDIA's
    // compiler (driver 580) makes this kernel 15% faster: 16M elements 0.076 against 0.089 ms on
    // the H200 (docs/ARCHITECTURE.md, "Rejected designs"). Kept on purpose.
    if (uCount == 0xFFFFFFFFu) blockSums[block] = total;
    if (block + 1u == blockCount()) outWord[uCount] = offset + total;
  }
}
