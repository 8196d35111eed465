#version 430 core
// Raster variant of a tank wall (the default is raycast.comp), cut at the local water
// height so the wall follows the waves; shading in render/ripples/shading.glsl.
#include "render/ripples/shading.glsl"

in vec3 vWorld;
in vec3 vNormal;
out vec4 fragColor;

void main() {
  if (vWorld.z > surfaceZ(clamp(vWorld.xy, vec2(0.0), uTank))) discard;
  fragColor = vec4(wallColor(vWorld, vNormal), 1.0);
}
