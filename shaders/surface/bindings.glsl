// Binding points and constants of the water-surface mesher (src/render/surface_mesher.h), shared
// by C++ and GLSL: only #define lines. Kernels use at most 4 of GL 4.3's 8 storage blocks.
#define SURFACE_POSITIONS 0     // vec4 particle positions (m, w = 1), read by the splat
#define SURFACE_DENSITY 1       // uint per grid corner: the normalised density in fixed point
#define SURFACE_TRI_COUNT 2     // uint per corner + 1: triangles of the cell at that corner, then scanned in place
#define SURFACE_VERT_COUNT 3    // uint per corner + 1: crossing edges the corner owns (+x, +y, +z), then scanned
#define SURFACE_VERTICES 4      // vec4 per vertex: position (m, w = 1)
#define SURFACE_NORMALS 5       // vec4 per vertex: unit outward normal (w = 0)
#define SURFACE_TRIANGLES 6     // uint x 3 per triangle: vertex indices, counter-clockwise from outside
#define SURFACE_CASES 0         // uniform block (std140): the marching-cubes case table, uvec4 per case
#define SURFACE_GROUP_SIZE 128  // local size of every surface kernel
#define SURFACE_FIXED_ONE 65536.0  // fixed-point units of a normalised density of 1 (the water at rest)
