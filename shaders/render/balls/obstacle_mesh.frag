#version 430 core
// Obstacle mesh, shaded as water-webgpu draws its obstacles: colour · (0.2·ambient + 0.8·(0.5 + 0.5·n·L)).
// The normal is turned toward the eye, so a mesh file's winding does not matter and the inside of
// a cup seen over its rim is lit as a surface facing us.
in vec3 vView;
in vec3 vNormal;

#include "render/balls/obstacle_light.glsl"

void main() {
  vec3 n = normalize(vNormal);
  if (dot(n, vView) > 0.0) n = -n;
  fragColor = vec4(uColor * (0.2 * ambientLight(n) + 0.8 * (0.5 + 0.5 * dot(n, uLightView))), 1.0);
}
