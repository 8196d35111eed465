// Stateless random numbers from integer hashes: the same (index, seed) gives the same value on
// every GPU, so a reset is reproducible. PCG hash (Jarzynski & Olano, "Hash Functions for GPU
// Rendering", JCGT 2020).
#ifndef COMMON_RANDOM_GLSL
#define COMMON_RANDOM_GLSL

uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// Uniform in [0, 1) with 24 random bits.
float random01(uint v) { return float(pcgHash(v) >> 8u) * (1.0 / 16777216.0); }

#endif
