// The divergence watch's health words (src/sim/divergence.h), shared by C++ and GLSL: only
// #define lines. A model's health kernel (common/health.glsl) reduces its state into these four
// 32-bit words; the model's C++ side reads them into a verdict.
#define HEALTH_BINDING 7     // storage block of the words; health kernels read their state at 0 and 1
#define HEALTH_NON_FINITE 0  // uint: elements with a NaN or infinite value
#define HEALTH_MAX_BITS 1    // floatBitsToUint of the largest watched magnitude (>= 0, so the bits order like it)
#define HEALTH_FLAGGED 2     // uint: elements the model flags (balls: outside the walls)
#define HEALTH_WORDS 4       // the last word is spare
