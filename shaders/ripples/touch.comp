#version 430 core
// Disturbs the surface with water-simulation-gpu's cosine bump:
//   h += depth · (cos(π·r/radius) + 1)/2  for r ≤ radius (r in cells, aspect-correct).
#include "ripples/bindings.glsl"

layout(local_size_x = RIPPLES_TILE, local_size_y = RIPPLES_TILE) in;
#include "ripples/cells.glsl"

layout(std430, binding = RIPPLES_STATE_OUT) buffer State { vec2 state[]; };

uniform vec2 uCentre;   // cells
uniform float uRadius;  // cells
uniform float uDepth;   // m (negative pushes the surface down)

const float kPi = 3.14159265358979;

void main() {
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, uSize))) return;
  const float r = length(vec2(p) + 0.5 - uCentre) / uRadius;
  if (r > 1.0) return;
  state[cellIndex(p)].x += uDepth * 0.5 * (cos(kPi * r) + 1.0);
}
