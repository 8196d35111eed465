#version 430 core
// Caustics: sunlight through a grid of surface points is refracted and followed to the floor,
// where each point lands as a 1-px additive splat (water-simulation-gpu's light particles).
#include "render/ripples_3d.glsl"

uniform ivec2 uLightGrid;  // light points along x and y
uniform vec3 uSunDir;      // towards the sun

void main() {
  const ivec2 q = ivec2(gl_VertexID % uLightGrid.x, gl_VertexID / uLightGrid.x);
  const vec2 xy = (vec2(q) + 0.5) / vec2(uLightGrid) * uTank;
  const vec3 p = vec3(xy, surfaceZ(xy));
  const vec3 r = refract(-normalize(uSunDir), surfaceNormal(xy), kEtaAirWater);
  const vec3 hit = p + r * (p.z / max(-r.z, 1e-3));
  // Light leaving one side re-enters on the other (as in the seed), so the floor has no dark edge.
  gl_Position = vec4(mod(hit.xy, uTank) / uTank * 2.0 - 1.0, 0.0, 1.0);
}
