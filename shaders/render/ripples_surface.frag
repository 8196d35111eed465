#version 430 core
// Water surface seen from above: the view ray refracts to the lit floor (absorbed along its
// path), reflects the sky with Schlick's Fresnel, plus a sun highlight.
#include "render/ripples_3d.glsl"
#include "render/ripples_shading.glsl"

uniform vec3 uEye;
uniform vec3 uSunDir;  // towards the sun
in vec3 vWorld;
out vec4 fragColor;

void main() {
  vec3 n = surfaceNormal(vWorld.xy);
  const vec3 v = normalize(vWorld - uEye);
  if (dot(n, v) > 0.0) n = -n;  // grazing views of steep waves
  const vec3 r = refract(v, n, kEtaAirWater);
  // The refracted ray ends on the floor, or on a wall if it leaves the tank first; a wall shows
  // the floor tile at its foot, dimmed.
  float t = vWorld.z / max(-r.z, 1e-3);
  const vec2 exitT = mix(-vWorld.xy, uTank - vWorld.xy, step(0.0, r.xy)) / (r.xy + vec2(1e-6));
  const float tWall = min(exitT.x, exitT.y);
  const bool onWall = tWall < t;
  t = min(t, tWall);
  const vec3 hit = vWorld + t * r;
  const vec3 below = absorb(floorColor(clamp(hit.xy, vec2(0.0), uTank)) * (onWall ? 0.6 : 1.0), t);
  const float fresnel = schlick(clamp(dot(-v, n), 0.0, 1.0));
  vec3 color = mix(below, sky(reflect(v, n)), fresnel);
  color += vec3(1.6) * pow(max(dot(reflect(-uSunDir, n), -v), 0.0), 600.0);
  fragColor = vec4(color, 1.0);
}
