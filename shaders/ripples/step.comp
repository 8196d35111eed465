#version 430 core
// One time step of the heightfield, symplectic Euler (= leapfrog for the height):
//   RULE_WAVE  v += dt·c²·∇²h / dx²,  v *= max(0, 1 − velDamping·dt),
//              h += (mean4 − h)·min(posDamping·dt, 1) (positional smoothing), h += dt·v
//              — the wave equation ∂²h/∂t² = c²∇²h with the 5-point Laplacian.
//   RULE_SEED  water-simulation-gpu's model: v += dt·(−k·h + c·(mean4 − h)), v *= friction, h += dt·v
// Heights of a 16x16 tile plus the 64 edge cells around it are staged in shared memory, so the
// neighbour reads come from shared memory: each invocation reads its own cell's (h, v) once
// (coalesced) and 64 of them one apron cell each (the stencil never reads the tile's corners).
#include "ripples/bindings.glsl"

layout(local_size_x = RIPPLES_TILE, local_size_y = RIPPLES_TILE) in;
#include "ripples/cells.glsl"

layout(std430, binding = RIPPLES_STATE_IN) readonly buffer StateIn { vec2 stateIn[]; };
layout(std430, binding = RIPPLES_STATE_OUT) writeonly buffer StateOut { vec2 stateOut[]; };

uniform float uDt;           // s
uniform float uWaveFactor;   // RULE_WAVE: c²·dt/dx² (1/s); RULE_SEED: propagation c
uniform float uVelDecay;     // velocity factor per step
uniform float uPosSmoothing; // RULE_WAVE: fraction of (mean4 − h) added per step
uniform float uElasticity;   // RULE_SEED: spring k toward the rest height
uniform int uSpongeCells;    // absorbing boundary: width of the sponge layer (0: none)
uniform float uSpongeDecay;  // velocity factor per step at the outermost cell

const int kTile = 18;  // 16 + apron on both sides
shared float sHeight[kTile * kTile];

void main() {
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  const ivec2 lid = ivec2(gl_LocalInvocationID.xy);
  // Invocations past the grid's edge load their boundary image (clamped or wrapped), which is
  // what the edge cells read as their outside neighbour.
  const vec2 own = stateIn[cellIndex(neighbourCell(p))];
  sHeight[(lid.y + 1) * kTile + lid.x + 1] = own.x;
  const int local = int(gl_LocalInvocationIndex);
  if (local < 64) {
    const int k = (local & 15) + 1;
    const int side = local >> 4;  // 0: row above, 1: row below, 2: column left, 3: column right
    const ivec2 a = side == 0 ? ivec2(k, 0) : side == 1 ? ivec2(k, kTile - 1) : side == 2 ? ivec2(0, k) : ivec2(kTile - 1, k);
    const ivec2 cell = neighbourCell(ivec2(gl_WorkGroupID.xy) * 16 - 1 + a);
    sHeight[a.y * kTile + a.x] = stateIn[cellIndex(cell)].x;
  }
  barrier();

  if (any(greaterThanEqual(p, uSize))) return;
  const ivec2 s = lid + 1;
  const float h = own.x;
  const float sum4 = sHeight[s.y * kTile + s.x - 1] + sHeight[s.y * kTile + s.x + 1] +
                     sHeight[(s.y - 1) * kTile + s.x] + sHeight[(s.y + 1) * kTile + s.x];
  float v = own.y;

#ifdef RULE_SEED
  v += uDt * (-uElasticity * h + uWaveFactor * (0.25 * sum4 - h));
  v *= uVelDecay;
  const float hSmoothed = h;
#else
  v += uWaveFactor * (sum4 - 4.0 * h);
  v *= uVelDecay;
  const float hSmoothed = h + (0.25 * sum4 - h) * uPosSmoothing;
#endif

  if (uSpongeCells > 0) {
    // Sponge: velocity decay that rises smoothly (quadratically) toward the border.
    const int edge = min(min(p.x, p.y), min(uSize.x - 1 - p.x, uSize.y - 1 - p.y));
    const float depth = max(0.0, 1.0 - float(edge) / float(uSpongeCells));
    v *= mix(1.0, uSpongeDecay, depth * depth);
  }
  stateOut[cellIndex(p)] = vec2(hSmoothed + uDt * v, v);
}
