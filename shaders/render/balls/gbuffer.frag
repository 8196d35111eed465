#version 430 core
// G-buffer pass (write mask R, G, A on attachment 0; own depth, less, write): per pixel the
// nearest ball's view-space normal xy (the billboard-local position), its linear view depth in
// metres, and its foam in attachment 1. Blue (thickness) belongs to the next pass.
#include "render/balls/sphere_fragment.glsl"

layout(location = 0) out vec4 gbuffer;  // RG normal xy, B untouched, A view depth (m, > 0)
layout(location = 1) out float foam;

void main() {
  const SphereHit hit = sphereFragment();
  gbuffer = vec4(hit.normal.xy, 0.0, -hit.point.z);
  foam = vFoam;
}
