// Work-group-wide exclusive scan and sum of one uint per invocation in shared memory
// (Blelloch 1990 up-sweep/down-sweep: 2 * (WG - 1) adds, 2 * log2(WG) barriers). It assumes no
// warp or subgroup size, only that WG is a power of two. Indices are padded by one word per
// 32 (SCAN_PAD) so that the tree's strided accesses spread over the shared-memory banks.
// Call from uniform control flow only: it contains barriers.
#ifndef GRID_SCAN_GROUP_GLSL
#define GRID_SCAN_GROUP_GLSL

#define SCAN_PAD(i) ((i) + ((i) >> 5u))

shared uint sTree[SCAN_PAD(WG)];

void groupSync() {
  memoryBarrierShared();
  barrier();
}

// Up-sweep: leaves partial sums at the tree's right nodes and returns the group's sum.
uint groupUpSweep(uint value) {
  const uint t = gl_LocalInvocationID.x;
  sTree[SCAN_PAD(t)] = value;
  uint stride = 1u;
  for (uint d = WG >> 1u; d > 0u; d >>= 1u) {
    groupSync();
    if (t < d) {
      const uint a = stride * (2u * t + 1u) - 1u, b = a + stride;
      sTree[SCAN_PAD(b)] += sTree[SCAN_PAD(a)];
    }
    stride <<= 1u;
  }
  groupSync();
  const uint total = sTree[SCAN_PAD(WG - 1u)];
  groupSync();  // everyone has read the root before anyone changes the tree again
  return total;
}

// Sum of `value` over the group (the same for every invocation).
uint groupSum(uint value) { return groupUpSweep(value); }

// Returns the sum of `value` over the invocations before this one; `total` gets the group's sum.
uint groupExclusiveScan(uint value, out uint total) {
  const uint t = gl_LocalInvocationID.x;
  total = groupUpSweep(value);
  if (t == 0u) sTree[SCAN_PAD(WG - 1u)] = 0u;
  uint stride = WG;
  for (uint d = 1u; d < WG; d <<= 1u) {  // down-sweep: push prefixes back to the leaves
    stride >>= 1u;
    groupSync();
    if (t < d) {
      const uint a = stride * (2u * t + 1u) - 1u, b = a + stride;
      const uint left = sTree[SCAN_PAD(a)];
      sTree[SCAN_PAD(a)] = sTree[SCAN_PAD(b)];
      sTree[SCAN_PAD(b)] += left;
    }
  }
  groupSync();
  const uint prefix = sTree[SCAN_PAD(t)];
  groupSync();  // the tree may be reused right after return
  return prefix;
}

#endif
