#define LIFE_POSITIONS 0  // per particle, (x, y, 0, species) in fp32 or fp16 (life/state.glsl), in cell order after the grid pass
#define LIFE_VELOCITIES 1  // per particle, (vx, vy, ax, ay) in fp32 or fp16; a is the last acceleration (Verlet)
#define LIFE_ACCELERATIONS 2  // vec2 per particle: the force pass's result (mass 1)
#define LIFE_FORCE_TABLE 3  // vec4 per species pair i*S + j: (strength, radius, |collisionStrength|, collisionRadius)
#define LIFE_CELL_START 4  // the grid's cellStart (uint per cell + 1)
#define LIFE_GROUP_PAIRS 5  // uint per work group: candidate pairs examined (benchmark variant only)
#define LIFE_SPECIES_COLORS 6  // vec4 per species: linear RGB + 1 (read by the renderer)
#define LIFE_FORCES_GROUP 64  // work-group size of forces.comp
#define LIFE_MAX_SPECIES 20  // kMaxSpecies: the force table lives in shared memory
#define LIFE_BRUTE_TILE 256  // work-group size and shared-memory tile of forces_brute.comp
