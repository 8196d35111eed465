#version 430 core
// Scan phase of the reduce-then-scan prefix sum (see src/grid/prefix_scan.h): each work group
// scans its block of kScanBlock uints in registers and shared memory, adds the block's offset
// (the scanned block sums of the level above: the "uniform add", fused into the store) and
// writes the exclusive prefix sums. The last block also writes the grand total to out[uCount].
// Safe in place (in and out the same buffer): every element is read and written by one invocation.
layout(local_size_x = WG) in;
#include "common/index.glsl"
#include "grid/scan_group.glsl"
#include "grid/scan_load.glsl"

layout(std430, binding = SCAN_OUT_VEC) writeonly buffer ScanOutVec { uvec4 outVec[]; };
layout(std430, binding = SCAN_OUT_WORD) writeonly buffer ScanOutWord { uint outWord[]; };
layout(std430, binding = SCAN_BLOCK_OFFSETS) readonly buffer BlockOffsets { uint blockOffsets[]; };

uniform uint uHasOffsets;  // 0 when this level is a single block (the top of the recursion)

shared uint sChunk[SCAN_PAD(WG * VECS)];  // per-chunk sums, then per-chunk prefixes, element order

void main() {
  const uint block = groupIndex();
  if (block >= blockCount()) return;  // spare groups of a dispatch spilled into y (whole group)
  const uint t = gl_LocalInvocationID.x;
  const bool last = block + 1u == blockCount();
  const bool partial = (block + 1u) * kScanBlock > uCount;

  // 1. Exclusive scan inside each 4-element chunk; chunk sums go to shared memory.
  uvec4 v[VECS];
  for (uint k = 0u; k < VECS; ++k) {
    const uvec4 x = loadChunk(block, k, partial);
    v[k] = uvec4(0u, x.x, x.x + x.y, x.x + x.y + x.z);
    sChunk[SCAN_PAD(k * WG + t)] = v[k].w + x.w;
  }
  groupSync();

  // 2. Each invocation scans VECS consecutive chunk sums, the group scans the invocation totals.
  uint local[VECS];
  uint run = 0u;
  for (uint j = 0u; j < VECS; ++j) {
    local[j] = run;
    run += sChunk[SCAN_PAD(t * VECS + j)];
  }
  uint total;
  const uint before = groupExclusiveScan(run, total);
  for (uint j = 0u; j < VECS; ++j) sChunk[SCAN_PAD(t * VECS + j)] = before + local[j];
  groupSync();

  // 3. Add chunk prefix and block offset, store (coalesced, like the loads).
  const uint offset = uHasOffsets != 0u ? blockOffsets[block] : 0u;
  for (uint k = 0u; k < VECS; ++k) {
    const uvec4 r = v[k] + (sChunk[SCAN_PAD(k * WG + t)] + offset);
    const uint c = chunkIndex(block, k);
    if (!partial) {
      outVec[c] = r;
    } else {
      for (uint j = 0u; j < 4u; ++j)
        if (4u * c + j < uCount) outWord[4u * c + j] = r[j];
    }
  }
  if (last && t == 0u) outWord[uCount] = offset + total;
}
