#version 430 core
// G-buffer pass (write mask R, G, A on attachment 0; own depth, less, write): per pixel the
// nearest ball's view-space normal xy (the billboard-local position), its linear view depth in
// metres, and its foam in attachment 1. Blue (thickness) belongs to the next pass.
#include "render/balls/sphere.glsl"

layout(depth_greater) out float gl_FragDepth;

in vec3 vQuadPoint;
flat in vec3 vCentre;
flat in float vFoam;

uniform mat4 uProj;
uniform float uRadius;

layout(location = 0) out vec4 gbuffer;  // RG normal xy, B untouched, A view depth (m, > 0)
layout(location = 1) out float foam;

void main() {
  SphereHit hit;
  if (!intersectSphere(vQuadPoint, vCentre, uRadius, hit)) discard;
  gl_FragDepth = windowDepth(uProj, hit.point);
  gbuffer = vec4(hit.normal.xy, 0.0, -hit.point.z);
  foam = vFoam;
}
