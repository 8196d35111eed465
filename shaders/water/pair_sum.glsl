// A work group's sum of two vec4 per invocation in a fixed tree (the loads' sums:
// water/loads_sum.comp, water/obstacle_loads_sum.comp), so that it is the same on every run.
// The including kernel's local size is LOADS_SUM_GROUP_SIZE (a power of two), and every
// invocation calls sumPairs(); sPairA[0] and sPairB[0] then hold the sums.
#ifndef WATER_PAIR_SUM_GLSL
#define WATER_PAIR_SUM_GLSL

shared vec4 sPairA[LOADS_SUM_GROUP_SIZE], sPairB[LOADS_SUM_GROUP_SIZE];

void sumPairs(vec4 a, vec4 b) {
  const uint t = gl_LocalInvocationIndex;
  sPairA[t] = a;
  sPairB[t] = b;
  barrier();
  for (uint stride = uint(LOADS_SUM_GROUP_SIZE) / 2u; stride > 0u; stride /= 2u) {
    if (t < stride) {
      sPairA[t] += sPairA[t + stride];
      sPairB[t] += sPairB[t + stride];
    }
    barrier();
  }
}

#endif
