// Binding points and the tile size of the ripples model, shared by C++ (src/sim/ripples) and GLSL.
#define RIPPLES_STATE_IN 0   // vec2 (height m, vertical velocity m/s) per cell, read
#define RIPPLES_STATE_OUT 1  // same layout, written
#define RIPPLES_TILE 16      // work-group edge of the cell kernels (step, touch, body): 16 x 16 cells
