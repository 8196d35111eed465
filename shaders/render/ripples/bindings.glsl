// Binding points of the ripples views (src/render/ripples_view*.cpp, ripples_caustics.cpp), shared
// by C++ and GLSL. Only #define lines: this file is valid in both languages. SSBO points start
// after the model's (ripples/bindings.glsl), whose state buffer the views read at the same time.
#define RIPPLES_VIEW_TILES 3          // SSBO: vec2 (min, max height m) per tile of dual cells
#define RIPPLES_VIEW_RANGE 4          // SSBO: uint[2], min and max height m over the grid (ordered bits)
#define RIPPLES_VIEW_LIGHT 5          // SSBO: uint light points landed per caustics texel
#define RIPPLES_VIEW_FLOOR_UNIT 0     // sampler: floor tiles (mipmapped, repeating)
#define RIPPLES_VIEW_CAUSTICS_UNIT 1  // sampler: light on the floor, 1 = flat water
#define RIPPLES_VIEW_COLOR_IMAGE 0    // image: the render target's RGBA8 colour
#define RIPPLES_VIEW_LIGHT_IMAGE 1    // image: light on the floor (R16F)
#define RIPPLES_VIEW_TILE 8           // dual cells along a tile's side
#define RIPPLES_VIEW_GROUP 8          // pixels along a work group's side (even: 2x2 quads)
