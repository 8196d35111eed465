// Shading shared by the 3D surface and tank walls: sky, lit floor (tiles x caustics), absorption.
#ifndef RENDER_RIPPLES_SHADING_GLSL
#define RENDER_RIPPLES_SHADING_GLSL

uniform sampler2D uFloor;     // tiles
uniform sampler2D uCaustics;  // light on the floor: 1 = flat water
uniform float uTileRepeat;    // tiles across the tank width
uniform vec3 uWaterColor;     // linear RGB
uniform float uViewDistance;  // world units of water that absorb ~63% (Beer-Lambert)
uniform float uAmbient;       // floor light without sun

vec3 sky(vec3 dir) { return mix(vec3(0.62, 0.68, 0.74), vec3(0.18, 0.32, 0.58), clamp(dir.z, 0.0, 1.0)); }

vec3 floorColor(vec2 xy) {
  const float light = uAmbient + (1.0 - uAmbient) * texture(uCaustics, xy / uTank).r;
  return texture(uFloor, xy * uTileRepeat).rgb * light;
}

vec3 absorb(vec3 color, float pathLength) { return mix(uWaterColor, color, exp(-pathLength / uViewDistance)); }

float schlick(float cosine) { return 0.02 + 0.98 * pow(1.0 - cosine, 5.0); }  // water, F0 = 0.02

#endif
