// Binding points and sizes of the loads' sum (shaders/water/loads_sum.comp), which
// water::BoundaryLoads (src/sim/water/boundary_loads.cpp) runs; shared by C++ and GLSL. Only
// #define lines.
#define LOADS_PARTIALS 0        // vec4 pairs per work group of the measuring kernel and slot (water/loads.glsl)
#define LOADS_SUMS 1            // vec4 pairs per chunk of work groups and slot
#define LOADS_SUM_GROUP_SIZE 128
