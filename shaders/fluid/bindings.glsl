// Binding points and the work-group size of the fluid model (src/sim/fluid), shared by C++ and
// GLSL: only #define lines. At most 8 storage blocks per kernel (GL 4.3's minimum); the
// obstacles' particles come through buffer textures (common/obstacle_bindings.glsl).
#define FLUID_POS 0            // vec4 positions x (m, w = 1), cell order: predict, velocity
#define FLUID_VEL_IN 1         // vec4 velocities (m/s, w = foam)
#define FLUID_PRED 2           // vec4 predicted positions p (m, w = foam until the velocity pass), cell order
#define FLUID_OUT 3            // vec4, written: predicted positions, velocities, statistics
#define FLUID_LAMBDA 4         // vec2 (lambda, rho/rho0) per particle; vec4 vorticity in the vorticity passes
#define FLUID_CELL_START 5     // uint per grid cell + 1 (grid/bindings.glsl's layout), cell = h / 2
#define FLUID_PRESSURE 6       // float per particle: Σ λ over the step's iterations (the pressure, fluid/pressure.comp)
#define FLUID_LOADS 7          // vec4 pairs per work group: the walls' shares of the corrections (water/loads.glsl)
#define FLUID_UNPUSHED 6       // vec4 per particle: Δp's corrected position before the obstacles' push (obstacle loads)
#define FLUID_OBSTACLE_PLACED 0   // obstacle loads: vec4 obstacle particles in the world, w = obstacle
#define FLUID_OBSTACLE_VOLUMES 1  // obstacle loads: vec4 (x = rest volume m³) per obstacle particle, same order
#define FLUID_SHARES 7         // obstacle loads: vec4 per obstacle particle, Σ share (water/obstacle_loads.glsl)
#define FLUID_MOMENTS 3        // obstacle loads: vec4 per obstacle particle, Σ moment
#ifndef FLUID_GROUP_SIZE
#define FLUID_GROUP_SIZE 128   // local size of every fluid kernel (one particle per invocation)
#endif
