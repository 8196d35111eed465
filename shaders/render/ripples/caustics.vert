#version 430 core
// Raster variant of the caustics (caustics.comp is the default): sunlight through a grid
// of surface points is refracted and followed to the floor, where each point lands as a 1-px
// additive splat (water-simulation-gpu's light particles).
#include "render/ripples/view_3d.glsl"

uniform ivec2 uLightGrid;  // light points along x and y

void main() {
  const ivec2 q = ivec2(gl_VertexID % uLightGrid.x, gl_VertexID / uLightGrid.x);
  const vec2 xy = (vec2(q) + 0.5) / vec2(uLightGrid) * uTank;
  gl_Position = vec4(causticLanding(xy) * 2.0 - 1.0, 0.0, 1.0);
}
