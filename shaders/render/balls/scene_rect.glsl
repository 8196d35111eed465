// The scene pass's rectangle (window pixels, max exclusive): it clears and draws the obstacle
// meshes' depth only inside it (src/render/balls_view.h, meshesWindowRect), so outside it the
// scene is at the far plane whatever the depth texture holds.
#ifndef RENDER_BALLS_SCENE_RECT_GLSL
#define RENDER_BALLS_SCENE_RECT_GLSL

uniform ivec2 uSceneMin;
uniform ivec2 uSceneMax;

bool inSceneRect(ivec2 px) { return all(greaterThanEqual(px, uSceneMin)) && all(lessThan(px, uSceneMax)); }

#endif
