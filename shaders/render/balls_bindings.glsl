// Binding points of the deferred balls renderer, shared by C++ (src/render/balls_*) and GLSL.
#define BALLS_VIEW_POSITIONS 0   // SSBO, vec4 per ball (simulation frame, m), read only
#define BALLS_VIEW_VELOCITIES 1  // SSBO, vec4 per ball (m/s, w = foam in [0, 1]), read only
#define BALLS_VIEW_MESH 2        // SSBO, obstacle mesh: 2 vec4 per vertex (position, normal), read only
#define BALLS_VIEW_BLUR_IN 0     // sampler unit / image unit of the blur's source (RGBA32F)
#define BALLS_VIEW_BLUR_OUT 1    // image unit of the blur's destination (RGBA32F)
#define BALLS_VIEW_GBUFFER 0     // compose: G-buffer (RG normal xy, B thickness m, A view depth m)
#define BALLS_VIEW_FOAM 1        // compose: foam of the nearest ball (R16F)
#define BALLS_VIEW_DEPTH 2       // compose: the balls' own DEPTH32F (window depth)
