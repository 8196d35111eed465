// Binding points and the work-group size of the balls model, shared by C++ (src/sim/balls) and
// GLSL: only #define lines. At most 8 storage blocks per kernel (GL 4.3's guaranteed minimum); the
// obstacles' particles come through buffer textures (common/obstacle_bindings.glsl).
#define BALLS_POS_IN 0         // vec4 (position m, w = 1), cell order
#define BALLS_VEL_IN 1         // vec4 (velocity m/s, w = foam), cell order
#define BALLS_POS_OUT 2        // vec4, written
#define BALLS_VEL_OUT 3        // vec4, written
#define BALLS_ACC 4            // vec4 acceleration m/s^2 (velocity Verlet)
#define BALLS_CELL_START 5     // uint per grid cell + 1 (grid/bindings.glsl's layout)
#define BALLS_STEP_OUT 2       // collide: vec4 new positions (Euler) or accelerations (velocity Verlet)
#define BALLS_NEXT_CELL_COUNT 6     // Euler's collide counts the balls into the next step's grid at the
#define BALLS_NEXT_INDEX_IN_CELL 7  // positions it writes: the grid's cellCount, indexInCell
#define BALLS_NEXT_PARTICLE_CELL 4  // and particleCell
#define BALLS_OBST_POSES 0     // uniform block (std140): each obstacle's pose and velocity (obstacle_poses.glsl)
#define BALLS_MAX_OBSTACLES 16
#define BALLS_LOADS 2          // walls' loads: vec4 pairs per work group (water/loads.glsl; reuses POS_OUT)
#define BALLS_OBSTACLE_PLACED 2  // obstacle loads: vec4 obstacle particles in the world, w = obstacle (reuses POS_OUT)
#define BALLS_SHARES 3         // obstacle loads: vec4 per obstacle particle, Σ share (water/obstacle_loads.glsl; reuses VEL_OUT)
#define BALLS_MOMENTS 4        // obstacle loads: vec4 per obstacle particle, Σ moment (reuses ACC)
#define BALLS_STATS 2          // stats pass: BALLS_STATS_VALUES floats per work group (stats_layout.glsl; reuses POS_OUT)
#define BALLS_REACH_BOUNDS 0   // reach_windows.comp: uvec2 per window, the balls in reach of its cells
#define BALLS_GROUP_SIZE 128   // local size of every balls kernel (one ball per invocation)
