// One work group's statistics reduced in shared memory: each invocation holds kValues floats,
// the group adds them (or takes their maximum where reducedByMax(k)) and its first invocation
// writes the kValues results at partials[group · kValues ...]; the CPU reduces the groups. The
// including kernel defines kValues, GROUP_SIZE (its local size), the `partials` buffer and
//   bool reducedByMax(int k);
// before including this file.
#ifndef COMMON_GROUP_REDUCE_GLSL
#define COMMON_GROUP_REDUCE_GLSL

shared float sValues[kValues][GROUP_SIZE];

void reduceGroup(float values[kValues]) {
  const uint t = gl_LocalInvocationIndex;
  for (int k = 0; k < kValues; ++k) sValues[k][t] = values[k];
  barrier();
  for (uint stride = uint(GROUP_SIZE) / 2u; stride > 0u; stride /= 2u) {
    if (t < stride)
      for (int k = 0; k < kValues; ++k) {
        const float other = sValues[k][t + stride];
        sValues[k][t] = reducedByMax(k) ? max(sValues[k][t], other) : sValues[k][t] + other;
      }
    barrier();
  }
  if (t == 0u)
    for (int k = 0; k < kValues; ++k) partials[groupIndex() * uint(kValues) + uint(k)] = sValues[k][0];
}

#endif
