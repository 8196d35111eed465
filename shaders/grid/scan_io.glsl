// Work groups, buffers, loads and stores of the scan's block kernels (scan_reduce, scan_block,
// scan_add): a group of WG invocations owns one block of WG * VECS uvec4 = WG * VECS * 4 uints.
// Invocation t owns the uvec4 chunks k * WG + t (k < VECS) of its block, so every load
// and store instruction of a group touches consecutive 16-byte chunks (coalesced). Full blocks
// use uvec4 accesses; the last block, which may be partial, uses uint accesses with bounds
// checks (reads past the end give 0), so buffers need no padding to a multiple of 16 bytes.
// In and out may be the same buffer: each element is read and written by the same invocation.
#ifndef GRID_SCAN_IO_GLSL
#define GRID_SCAN_IO_GLSL

layout(local_size_x = WG) in;
#include "common/index.glsl"
#include "grid/bindings.glsl"

const uint kScanBlock = WG * VECS * 4u;  // elements per work group

layout(std430, binding = SCAN_IN_VEC) readonly buffer ScanInVec { uvec4 inVec[]; };
layout(std430, binding = SCAN_IN_WORD) readonly buffer ScanInWord { uint inWord[]; };
layout(std430, binding = SCAN_OUT_VEC) writeonly buffer ScanOutVec { uvec4 outVec[]; };
layout(std430, binding = SCAN_OUT_WORD) writeonly buffer ScanOutWord { uint outWord[]; };
layout(std430, binding = SCAN_BLOCK_SUMS) buffer BlockSums { uint blockSums[]; };

uniform uint uCount;  // elements at this level

// Number of blocks at this level (at least one, so that a scan of 0 elements writes its total).
uint blockCount() { return max(1u, (uCount + kScanBlock - 1u) / kScanBlock); }

// True for the last block when it is not full (it takes the bounds-checked uint path).
bool partialBlock(uint block) { return (block + 1u) * kScanBlock > uCount; }

// This work group's block and whether it is the partial last one; false for the spare groups of
// a dispatch spilled into y, which return at once (the whole group).
bool groupBlock(out uint block, out bool partial) {
  block = groupIndex();
  partial = partialBlock(block);
  return block < blockCount();
}

// Chunk index (in uvec4 units) of the k-th chunk this invocation owns in block `block`.
uint chunkIndex(uint block, uint k) { return block * (WG * VECS) + k * WG + gl_LocalInvocationID.x; }

uvec4 loadChunk(uint block, uint k, bool partial) {
  const uint c = chunkIndex(block, k);
  if (!partial) return inVec[c];
  uvec4 v = uvec4(0u);
  for (uint j = 0u; j < 4u; ++j)
    if (4u * c + j < uCount) v[j] = inWord[4u * c + j];
  return v;
}

void storeChunk(uint block, uint k, bool partial, uvec4 v) {
  const uint c = chunkIndex(block, k);
  if (!partial) {
    outVec[c] = v;
    return;
  }
  for (uint j = 0u; j < 4u; ++j)
    if (4u * c + j < uCount) outWord[4u * c + j] = v[j];
}

#endif
