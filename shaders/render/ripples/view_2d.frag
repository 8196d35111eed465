#version 430 core
// Raster variant of the 2D ripples view (view_2d.comp is the default): one full-screen
// triangle, the floor sampled with the fragment's own derivatives. Kept to check the compute
// view against (tests, `bench ripples --renderer raster`).
#include "render/ripples/view_2d.glsl"

in vec2 vUv;
out vec4 fragColor;

void main() {
  const vec2 uv = vUv * uUvScale + uUvOffset;
  const TopView s = topViewRay(uv);
  fragColor = vec4(topViewColor(s, uv, texture(uFloor, s.tileUv).rgb), 1.0);
}
