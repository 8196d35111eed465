#version 430 core
// A sphere moving through the surface pushes water aside: where its submerged column grows the
// surface is pushed down, where it shrinks the water flows back (h += coupling * (before - now)).
// Heights in m; positions in m from the grid's corner, z relative to the rest surface.
//   After Ten Minute Physics #20 (height-field water with bodies, coupling alpha = 0.5).
#include "ripples/bindings.glsl"

layout(local_size_x = RIPPLES_TILE, local_size_y = RIPPLES_TILE) in;
#include "ripples/cells.glsl"

layout(std430, binding = RIPPLES_STATE_OUT) buffer State { vec2 state[]; };

uniform vec3 uBefore;     // sphere centre at the start of the step, m
uniform vec3 uNow;        // and at its end
uniform float uRadius;    // m
uniform float uCellSize;  // m
uniform float uCoupling;  // fraction of the displaced column moved per step

// Height of the water column below the rest surface occupied by the sphere at `xy`, faded out
// over the last three cells of its rim: the bare profile's infinite slope there would excite
// grid-scale waves.
float submerged(vec3 centre, vec2 xy) {
  const float r = length(xy - centre.xy);
  if (r >= uRadius) return 0.0;
  const float halfChord = sqrt(uRadius * uRadius - r * r);
  const float rim = smoothstep(uRadius, max(uRadius - 3.0 * uCellSize, 0.0), r);
  return rim * clamp(halfChord - centre.z, 0.0, 2.0 * halfChord);
}

void main() {
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, uSize))) return;
  const vec2 xy = (vec2(p) + 0.5) * uCellSize;
  state[cellIndex(p)].x += uCoupling * (submerged(uBefore, xy) - submerged(uNow, xy));
}
