// World placement of the ripples tank for the 3D view: x in [0,1], y in [0, height/width],
// floor at z = 0, rest water level at z = uWaterLevel; heights exaggerated by uExaggeration.
#ifndef RENDER_RIPPLES_3D_GLSL
#define RENDER_RIPPLES_3D_GLSL

#include "render/ripples_surface.glsl"

uniform vec2 uTank;            // world extent (1, height/width)
uniform float uWaterLevel;     // world units
uniform float uExaggeration;   // height and slope exaggeration (1 = physical)

const float kEtaAirWater = 1.0 / 1.333;

vec2 gridUv(vec2 xy) { return xy / uTank; }

float surfaceZ(vec2 xy) {
  return uWaterLevel + heightBilinear(gridUv(xy)) * uExaggeration / (float(uSize.x) * uCellSize);
}

vec3 surfaceNormal(vec2 xy) { return normalize(vec3(-slopeBilinear(gridUv(xy)) * uExaggeration, 1.0)); }

#endif
