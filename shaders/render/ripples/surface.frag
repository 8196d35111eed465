#version 430 core
// Raster variant of the 3D view's water surface (the default is raycast.comp): shading
// in render/ripples/shading.glsl, the floor sampled with the fragment's derivatives.
#include "render/ripples/shading.glsl"

in vec3 vWorld;
out vec4 fragColor;

void main() {
  const WaterView w = waterView(vWorld);
  fragColor = vec4(waterColor(w, texture(uFloor, w.floorXy * uTileRepeat).rgb), 1.0);
}
