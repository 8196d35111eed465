// Binding points and sizes of the loads' sums (shaders/water/loads_sum.comp and
// obstacle_loads_sum.comp), which water::BoundaryLoads (src/sim/water/boundary_loads.cpp) runs;
// shared by C++ and GLSL. Only #define lines.
#define LOADS_PARTIALS 0        // the walls: two vec4 per work group of the measuring kernel (water/loads.glsl)
#define LOADS_SUMS 1            // two vec4 per obstacle (Σ share, Σ moment), then two per chunk of the walls' groups
#define LOADS_SHARES 2          // vec4 per obstacle particle: Σ share (water/obstacle_loads.glsl)
#define LOADS_MOMENTS 3         // vec4 per obstacle particle: Σ moment
#define LOADS_SUM_GROUP_SIZE 128
