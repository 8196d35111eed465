#version 430 core
// One pass of the naive Hillis-Steele scan (Hillis & Steele 1986, as in the particle-life
// article): out[i] = in[i] + in[i - uStride] over uCount + 1 elements, log2(N) passes of
// O(N) work each. Kept as the reference for tests and the benchmark, not for use.
// The first pass (uShift = 1) also shifts by one, so the inclusive passes produce the
// exclusive scan with the total in the extra last entry.
layout(local_size_x = 256) in;
#include "common/index.glsl"
#include "grid/bindings.glsl"

layout(std430, binding = SCAN_NAIVE_IN) readonly buffer NaiveIn { uint naiveIn[]; };
layout(std430, binding = SCAN_NAIVE_OUT) writeonly buffer NaiveOut { uint naiveOut[]; };

uniform uint uCount;   // elements of the input; the output has uCount + 1
uniform uint uStride;  // 2^pass
uniform uint uShift;   // 1 on the first pass: read in[i - 1] for element i (0 for i = 0)

uint value(uint i) {
  if (uShift == 0u) return naiveIn[i];
  return i > 0u ? naiveIn[i - 1u] : 0u;
}

void main() {
  const uint i = globalIndex();
  if (i > uCount) return;
  naiveOut[i] = value(i) + (i >= uStride ? value(i - uStride) : 0u);
}
