// The partial statistics fluid/stats.comp writes per work group, shared by C++ (the probe in
// src/sim/fluid/density_probe.cpp checks the offsets at compile time) and GLSL: only #define
// lines. Each is a float; the CPU adds the groups' sums (in double) and takes the largest maxima.
#define FLUID_STATS_KINETIC 0       // sum: ½|v|², m²/s² (the CPU multiplies by the mass)
#define FLUID_STATS_POTENTIAL 1     // sum: −g·(x − domain min), m²/s²
#define FLUID_STATS_COMPRESSION 2   // sum: max(ρ/ρ0 − 1, 0)
#define FLUID_STATS_DENSITY 3       // sum: ρ/ρ0 − 1 (signed: a free surface reads below 0)
#define FLUID_STATS_MAX_COMPRESSION 4  // max: ρ/ρ0 − 1
#define FLUID_STATS_MAX_SPEED 5     // max: m/s
#define FLUID_STATS_NON_FINITE 6    // sum: particles with NaN or infinite state
#define FLUID_STATS_OUTSIDE 7       // sum: particles outside the walls
#define FLUID_STATS_FRONT 8         // max: the largest x of particles within one spacing of the floor
#define FLUID_STATS_BACK_HEIGHT 9   // max: the largest z of particles within one spacing of the back (x min) wall
#define FLUID_STATS_VALUES 10
