// The partial statistics stats.comp writes per work group, shared by C++ (balls::GroupStats in
// src/sim/balls/balls_passes.cpp, which checks the offsets at compile time) and GLSL: only
// #define lines. Each is a float; the CPU adds the groups' sums and takes the largest maxima.
#define BALLS_STATS_KINETIC 0      // sum: kinetic energy, Σ ½|v|² per unit mass
#define BALLS_STATS_POTENTIAL 1    // sum: potential energy, Σ −g·(x − domain min)
#define BALLS_STATS_OVERLAP 2      // sum: Σ overlap / r over contacts (each pair seen from both sides)
#define BALLS_STATS_CONTACTS 3     // sum: contacts
#define BALLS_STATS_MAX_OVERLAP 4  // max: overlap / r
#define BALLS_STATS_MAX_SPEED 5    // max: speed, m/s
#define BALLS_STATS_NON_FINITE 6   // sum: balls with NaN or infinite state
#define BALLS_STATS_OUTSIDE 7      // sum: balls outside the walls
#define BALLS_STATS_FRONT 8        // max: surge front, the largest x of balls within 2r of the floor (−inf: none)
#define BALLS_STATS_BACK_HEIGHT 9  // max: column height, the largest z of balls within 2r of the back (x min) wall
#define BALLS_STATS_VALUES 10      // floats per work group
