#version 430 core
// A tank wall: water seen through glass, darker with depth, cut at the local water height so the
// wall follows the waves; a faint sky reflection on the glass.
#include "render/ripples_3d.glsl"
#include "render/ripples_shading.glsl"

uniform vec3 uEye;
in vec3 vWorld;
in vec3 vNormal;
out vec4 fragColor;

void main() {
  const float surface = surfaceZ(clamp(vWorld.xy, vec2(0.0), uTank));
  if (vWorld.z > surface) discard;
  const vec3 v = normalize(vWorld - uEye);
  const float depth = surface - vWorld.z;
  // Looking in through the wall: light coloured water, lit by the caustics at the wall's foot and
  // absorbed more with depth below the surface.
  const vec2 foot = clamp(vWorld.xy - vNormal.xy * 0.01, vec2(0.0), uTank);
  const float light = uAmbient + (1.0 - uAmbient) * texture(uCaustics, foot / uTank).r;
  const vec3 inside = absorb(vec3(0.55, 0.72, 0.76) * light, 0.1 + 1.5 * depth);
  const float fresnel = 0.5 * schlick(clamp(dot(-v, vNormal), 0.0, 1.0));
  const float rim = smoothstep(0.006, 0.0, depth);  // bright meniscus line at the surface
  fragColor = vec4(mix(inside, sky(reflect(v, vNormal)), fresnel) + vec3(0.35 * rim), 1.0);
}
