// World placement of the ripples tank for the 3D view: x in [0,1], y in [0, height/width],
// floor at z = 0, rest water level at z = uWaterLevel; heights exaggerated by uExaggeration.
#ifndef RENDER_RIPPLES_VIEW_3D_GLSL
#define RENDER_RIPPLES_VIEW_3D_GLSL

#include "render/ripples/surface.glsl"

uniform vec2 uTank;            // world extent (1, height/width)
uniform float uWaterLevel;     // world units
uniform float uExaggeration;   // height and slope exaggeration (1 = physical)
uniform vec3 uSunDir;          // towards the sun, unit

const float kEtaAirWater = 1.0 / 1.333;

vec2 gridUv(vec2 xy) { return xy / uTank; }

float worldZ(float height) { return uWaterLevel + height * uExaggeration / (float(uSize.x) * uCellSize); }

float surfaceZ(vec2 xy) { return worldZ(heightBilinear(gridUv(xy))); }

vec3 surfaceNormal(vec2 xy) { return normalize(vec3(-slopeBilinear(gridUv(xy)) * uExaggeration, 1.0)); }

// Caustics: where sunlight through the surface point above xy, refracted, meets the floor. Light
// leaving one side re-enters on the other (as in the seed), so the floor has no dark edge; the
// result is in [0,1)^2 of the floor (the caustics texture's uv).
vec2 causticLanding(vec2 xy) {
  const vec3 p = vec3(xy, surfaceZ(xy));
  const vec3 r = refract(-uSunDir, surfaceNormal(xy), kEtaAirWater);
  const vec3 hit = p + r * (p.z / max(-r.z, 1e-3));
  return mod(hit.xy, uTank) / uTank;
}

#endif
