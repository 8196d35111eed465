#version 430 core
// Caustics, third pass: the sunlight on each floor texel under the water, as a share of what
// falls on dry floor (1). Sunlight crosses every horizontal plane evenly, so the light through
// the surface over the point s (xy, box frame) is the same for every s; refracted there it lands
// on the floor at
//   L(s) = s + h(s) t.xy / (−t.z),   t = refract(−sun, n(s), 1 / index)
// (h the smoothed height of caustics_smooth.comp, n its normal; dry floor: L(s) = s). The light
// at a floor point F is then 1 / |det ∂L/∂s| at the s that lands there: found by iterating
// s ← F − h(s) t.xy / (−t.z), the Jacobian by central differences a cell apart. The water's edge
// (wet next to dry) is neither a slope nor a change of L: differences stop at it. Where the
// surface focuses the light the determinant nears 0: the light is capped at kMaxLight. A point
// whose s falls outside the box takes the dry floor's light. Clears the tops read by the earlier
// passes, for the next frame.
#include "render/balls/bindings.glsl"
layout(local_size_x = 16, local_size_y = 16) in;

layout(std430, binding = BALLS_VIEW_CAUSTICS_TOPS) writeonly buffer Tops { uint tops[]; };
layout(binding = BALLS_VIEW_CAUSTICS_HEIGHT) uniform sampler2D uHeight;  // m above the floor, 0: dry
layout(binding = BALLS_VIEW_CAUSTICS_LIGHT_IMAGE, r16f) writeonly uniform image2D uLight;
uniform ivec2 uCells;
uniform vec2 uCellSize;   // m
uniform vec3 uSunBox;     // towards the sun, box frame, unit, above the horizon
uniform float uEta;       // 1 / the water's index of refraction
uniform float uStrength;  // the light written: 1 + uStrength (light − 1)

const float kMaxLight = 6.0;
const int kIterations = 4;

vec2 extent() { return vec2(uCells) * uCellSize; }

// The water's height over s (m from the floor's corner): linear between the cell centres about
// it that hold water, 0 where the cell s is in is dry or covered, so the water's edge stays an
// edge instead of a slope down to the floor.
float heightAt(vec2 s) {
  const ivec2 last = uCells - 1;
  if (texelFetch(uHeight, clamp(ivec2(floor(s / uCellSize)), ivec2(0), last), 0).r <= 0.0) return 0.0;
  const vec2 t = s / uCellSize - 0.5;
  const ivec2 i = ivec2(floor(t));
  const vec2 f = t - vec2(i);
  float sum = 0.0, weight = 0.0;
  for (int k = 0; k < 4; ++k) {
    const ivec2 corner = ivec2(k & 1, k >> 1);
    const float h = texelFetch(uHeight, clamp(i + corner, ivec2(0), last), 0).r;
    const vec2 along = mix(1.0 - f, f, vec2(corner));
    const float w = along.x * along.y;
    if (h > 0.0) sum += w * h, weight += w;
  }
  return weight > 0.0 ? sum / weight : 0.0;
}

// The slope of the water's top along `axis` at s from the heights a cell to either side, leaving
// out a dry side (the water's edge is not a slope the light refracts on): one-sided next to it,
// level where both sides are dry.
float slopeAt(vec2 s, vec2 axis, float h) {
  const float a = heightAt(s + axis), b = heightAt(s - axis), step = length(axis);
  if (a > 0.0 && b > 0.0) return (a - b) / (2.0 * step);
  if (a > 0.0) return (a - h) / step;
  if (b > 0.0) return (h - b) / step;
  return 0.0;
}

// How far the ray through the surface over s travels sideways on its way down to the floor
// (xy), and whether s is under water (z: 1 wet, 0 dry).
vec3 offset(vec2 s) {
  const float h = heightAt(s);
  if (h <= 0.0) return vec3(0.0);
  const vec2 slope = vec2(slopeAt(s, vec2(uCellSize.x, 0.0), h), slopeAt(s, vec2(0.0, uCellSize.y), h));
  const vec3 t = refract(-uSunBox, normalize(vec3(-slope, 1.0)), uEta);
  return vec3(h * t.xy / max(-t.z, 0.05), 1.0);
}

// ∂offset/∂s along `axis` (a cell long) at s, from neighbours on the same side of the water's
// edge as s: central, one-sided next to the edge, 0 between two edges.
vec2 offsetChange(vec2 s, vec2 axis, vec3 here) {
  const vec3 a = offset(s + axis), b = offset(s - axis);
  const float step = length(axis);
  if (a.z == here.z && b.z == here.z) return (a.xy - b.xy) / (2.0 * step);
  if (a.z == here.z) return (a.xy - here.xy) / step;
  if (b.z == here.z) return (here.xy - b.xy) / step;
  return vec2(0.0);
}

void main() {
  const ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(cell, uCells))) return;
  const vec2 floorPoint = (vec2(cell) + 0.5) * uCellSize;
  vec2 s = floorPoint;
  for (int k = 0; k < kIterations; ++k) s = floorPoint - offset(s).xy;
  float light = 1.0;
  if (all(greaterThanEqual(s, vec2(0.0))) && all(lessThanEqual(s, extent()))) {
    const vec3 here = offset(s);
    const vec2 dx = vec2(1.0, 0.0) + offsetChange(s, vec2(uCellSize.x, 0.0), here);
    const vec2 dy = vec2(0.0, 1.0) + offsetChange(s, vec2(0.0, uCellSize.y), here);
    light = min(1.0 / max(abs(dx.x * dy.y - dx.y * dy.x), 1e-6), kMaxLight);
  }
  imageStore(uLight, cell, vec4(1.0 + uStrength * (light - 1.0), 0.0, 0.0, 0.0));
  tops[cell.y * uCells.x + cell.x] = 0u;
}
