// Floats as uints that sort the same way, for atomicMin / atomicMax on floats (GL 4.3 has no
// float atomics): flip all bits of negatives, only the sign bit of the rest.
//   orderedBits(-1.0) < orderedBits(-0.5) < orderedBits(0.0) < orderedBits(2.0)
#ifndef COMMON_ORDERED_FLOAT_GLSL
#define COMMON_ORDERED_FLOAT_GLSL

uint orderedBits(float f) {
  const uint u = floatBitsToUint(f);
  return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}

float fromOrderedBits(uint u) { return uintBitsToFloat((u & 0x80000000u) != 0u ? u & 0x7fffffffu : ~u); }

#endif
