// The caustics' floor cells (render/balls/caustics_*.comp): each holds the water's top over the
// floor as a float's bits (0: no water), or kCovered where an obstacle's ball lies over the cell.
#ifndef RENDER_BALLS_CAUSTICS_CELLS_GLSL
#define RENDER_BALLS_CAUSTICS_CELLS_GLSL
#ifndef COVER
#define COVER 0
#endif
const uint kCovered = 0xFFFFFFFFu;
#endif
