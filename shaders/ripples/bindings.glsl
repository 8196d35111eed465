// Binding points of the ripples model, shared by C++ (src/sim/ripples) and GLSL.
#define RIPPLES_STATE_IN 0   // vec2 (height m, vertical velocity m/s) per cell, read
#define RIPPLES_STATE_OUT 1  // same layout, written
#define RIPPLES_HEALTH 2     // divergence watch: max |h| bits, max |v| bits, non-finite count
