#version 430 core
// Sphere impostor: discards outside the disc, writes the true sphere depth (so neighbouring
// balls intersect correctly) and shades with a key light, sky ambient and foam tint.
in vec2 vLocal;
in vec3 vCentreView;
in float vFoam;

uniform mat4 uProj;
uniform float uRadius;
#include "render/balls/obstacle_light.glsl"

void main() {
  const float r2 = dot(vLocal, vLocal);
  if (r2 > 1.0) discard;
  const vec3 n = vec3(vLocal, sqrt(1.0 - r2));
  const vec3 surface = vCentreView + uRadius * n;
  const vec4 clip = uProj * vec4(surface, 1.0);
  gl_FragDepth = 0.5 * clip.z / clip.w + 0.5;
  const vec3 albedo = mix(uColor, vec3(1.0, 1.2, 1.4), clamp(vFoam, 0.0, 1.0));
  const float diffuse = max(dot(n, uLightView), 0.0);
  const float spec = pow(max(dot(reflect(-uLightView, n), vec3(0, 0, 1)), 0.0), 40.0);
  fragColor = vec4(albedo * (0.35 * ambientLight(n) + 0.65 * diffuse) + vec3(0.25 * spec), 1.0);
}
