#define GRID_POSITIONS 0  // positions (vec4 xyz + w, or uvec2 half xy + word: grid/positions.glsl), read by count and the rank-scatter
#define GRID_PARTICLE_CELL_OUT 3  // uint per particle, its cell, written by the count pass (shares 3: no permutation there)
#define GRID_PARTICLE_CELL 0  // the same cells, read by the reorder passes in place of the positions
#define GRID_INDEX_IN_CELL 1  // uint per particle, the count pass's atomicAdd result
#define GRID_CELL_COUNT 2  // uint per cell, atomicAdd target (count pass only, so it shares 2)
#define GRID_CELL_START 2  // uint per cell + 1, exclusive scan of the counts (reorder pass)
#define GRID_PERMUTATION 3  // uint per particle, permutation[sorted] = original (optional)
#define GRID_REORDER_SRC 4  // first of GRID_REORDER_MAX_ARRAYS consecutive source arrays
#define GRID_MEMBERS 4  // uint per particle, the stable grid's cell members (rank pass only, so it shares 4)
#define GRID_REORDER_DST 6  // first of GRID_REORDER_MAX_ARRAYS consecutive destination arrays
#define GRID_STABLE_MAX_CELL 1024  // larger cells keep their atomicAdd order (grid_rank.comp)
#define GRID_REORDER_MAX_ARRAYS 2  // arrays per reorder pass: bindings 0..7 fit GL 4.3's minimum of 8
#define SCAN_IN_VEC 0  // scan input as uvec4 (full blocks)
#define SCAN_IN_WORD 1  // the same buffer as uint (the last, partial block)
#define SCAN_OUT_VEC 2  // scan output as uvec4
#define SCAN_OUT_WORD 3  // the same buffer as uint (partial block, the total, block sums)
#define SCAN_BLOCK_SUMS 4  // block sums of this level (scanned in place, they are the block offsets)
#define SCAN_BLOCK_SUMS_VEC 5  // the same block sums as uvec4 (fused levels sum them in scan_block)
#define SCAN_NAIVE_IN 0  // Hillis-Steele pass input
#define SCAN_NAIVE_OUT 1  // Hillis-Steele pass output
