// Sampler units of the obstacles' particles (src/sim/water/obstacles.h), shared by C++ and GLSL:
// only #define lines. Kernels read them through buffer textures (common/obstacle_grid.glsl), so
// the obstacles take none of a kernel's 8 storage blocks (GL 4.3's minimum).
#define OBSTACLE_POS_UNIT 0         // vec4 per obstacle particle (world, w = obstacle index), grid order
#define OBSTACLE_CELL_START_UNIT 1  // uint per obstacle-grid cell + 1 (grid/bindings.glsl's layout)
#define OBSTACLE_VOLUME_UNIT 2      // vec4 (x = rest volume, m³) per obstacle particle, grid order (fluid)
