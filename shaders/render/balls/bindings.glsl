// Binding points of the deferred balls renderer, shared by C++ (src/render/balls_*) and GLSL.
#define BALLS_VIEW_POSITIONS 0       // SSBO, vec4 per ball (simulation frame, m), read only
#define BALLS_VIEW_VELOCITIES 1      // SSBO, vec4 per ball (m/s, w = foam in [0, 1]), read only
#define BALLS_VIEW_MESH 2            // SSBO, obstacle mesh: 2 vec4 per vertex (position, normal), read only
#define BALLS_VIEW_SPLAT_KEYS 3      // SSBO, compute raster: uint per pixel (depth key, then tagged ball id)
#define BALLS_VIEW_SPLAT_THICKNESS 4 // SSBO, compute raster: uint per pixel (fixed-point thickness)
#define BALLS_VIEW_SPLAT_BIG 5       // SSBO, compute raster: big balls' indirect dispatch header + list
#define BALLS_VIEW_CELL_COUNT 6      // SSBO, grid cells view: the balls grid's uint count per cell, read only
#define BALLS_VIEW_CELL_SCAN 7       // SSBO, grid cells view: 1 per non-empty cell, then scanned in place (cells + 1 uints)
#define BALLS_VIEW_CELL_LIST 2       // SSBO, grid cells view: indirect draw command + non-empty cell ids (the
                                     // mesh's number: its passes never run with the mesh bound)
#define BALLS_VIEW_BLUR_IN 0         // sampler unit / image unit of the blur's source (RGBA32F)
#define BALLS_VIEW_BLUR_OUT 1        // image unit of the blur's destination (RGBA32F)
#define BALLS_VIEW_GBUFFER 0         // compose: G-buffer (RG normal xy, B thickness m, A view depth m)
#define BALLS_VIEW_FOAM 1            // compose: foam of the nearest ball (R16F)
#define BALLS_VIEW_DEPTH 2           // compose: the balls' own window depth (DEPTH32F or R32F)
#define BALLS_VIEW_SCENE_DEPTH 3     // compute raster and compose: sampler unit of the scene's DEPTH32F
#define BALLS_VIEW_COMPOSE_TARGET 0  // compose: image unit of the target's colour (RGBA8, read and written)
#define BALLS_VIEW_SPLAT_SURFACE 0   // compute raster resolve: image unit of the G-buffer surface
#define BALLS_VIEW_SPLAT_FOAM 1      // compute raster resolve: image unit of the foam (R16F)
#define BALLS_VIEW_SPLAT_DEPTH 2     // compute raster resolve: image unit of the window depth (R32F)
#define BALLS_VIEW_CAUSTICS_TOPS 3           // SSBO, caustics: uint per floor cell, the water's top (float bits, 0 dry)
#define BALLS_VIEW_CAUSTICS_HEIGHT 0         // caustics light pass: sampler unit of the smoothed height (R32F)
#define BALLS_VIEW_CAUSTICS_HEIGHT_IMAGE 0   // caustics smooth pass: image unit of the smoothed height
#define BALLS_VIEW_CAUSTICS_LIGHT_IMAGE 1    // caustics light pass: image unit of the light (R16F)
#define BALLS_VIEW_CAUSTICS 4                // compose: sampler unit of the caustics' light on the floor
