#version 430 core
// Particle-life forces through the uniform grid (src/sim/life/life.h): for particle i of
// species s, F = -centralForce·p + sum over j != i within R_sj of
//   (strength·max(0, 1 - d/R) - collisionStrength·max(0, 1 - d/Rc)) · (p_j - p_i)/d.
// Positions are in cell order (grid reorder), so each visited cell is one contiguous range.
// Per axis, the visited cells are those within the species' largest radius of the particle:
// 2 or 3 cells (the 3x3 block at most), plus, with LOOPING, the part wrapped round the other
// side of the box, trimmed so that no cell is visited twice even when the last cell is partial.
// With COUNT_PAIRS each work group writes how many candidate pairs it examined (benchmarks).
#include "life/bindings.glsl"
layout(local_size_x = LIFE_FORCES_GROUP) in;
#include "common/index.glsl"
#include "common/grid.glsl"
#include "life/box.glsl"
#include "life/pair_force.glsl"
#include "life/state.glsl"

layout(std430, binding = LIFE_POSITIONS) readonly buffer Positions { LifePosition positions[]; };
layout(std430, binding = LIFE_ACCELERATIONS) writeonly buffer Accelerations { vec2 accelerations[]; };
layout(std430, binding = LIFE_FORCE_TABLE) readonly buffer ForceTable { vec4 forceTable[]; };
layout(std430, binding = LIFE_CELL_START) readonly buffer CellStart { uint cellStart[]; };
#if COUNT_PAIRS
layout(std430, binding = LIFE_GROUP_PAIRS) writeonly buffer GroupPairs { uint groupPairs[]; };
shared uint sPairs;
#endif

uniform uint uCount;          // particles
uniform uint uSpecies;        // S
uniform float uCentralForce;  // 1/s^2

shared vec4 sTableA[LIFE_MAX_SPECIES * LIFE_MAX_SPECIES];  // shapePair() of each entry
shared float sTableB[LIFE_MAX_SPECIES * LIFE_MAX_SPECIES];
shared float sReach[LIFE_MAX_SPECIES];  // largest radius of each species' row

// Cells along one axis holding every point within `reach` of x: r0 directly, r1 wrapped round
// the box (LOOPING); a range with x > y is empty.
void axisRanges(float x, float reach, int axis, out ivec2 r0, out ivec2 r1) {
  const float origin = uGridOrigin[axis], extent = uBoxSize[axis];
  const int last = int(uGridDims[axis]) - 1;
  const int lo = int(floor(clamp((x - reach - origin) * uGridInvCellSize, -1.0, float(last + 1))));
  const int hi = int(floor(clamp((x + reach - origin) * uGridInvCellSize, -1.0, float(last + 1))));
  r0 = ivec2(max(lo, 0), min(hi, last));
  r1 = ivec2(1, 0);
#if LOOPING
  if (lo < 0) {
    const int a = int(floor(clamp((x - reach + extent - origin) * uGridInvCellSize, 0.0, float(last))));
    r1 = ivec2(max(a, r0.y + 1), last);
  } else if (x + reach >= origin + extent) {
    const int b = int(floor(clamp((x + reach - extent - origin) * uGridInvCellSize, 0.0, float(last))));
    r1 = ivec2(0, min(b, r0.x - 1));
  }
#endif
}

void main() {
  const uint pairs = uSpecies * uSpecies;
  for (uint k = gl_LocalInvocationID.x; k < pairs; k += gl_WorkGroupSize.x) shapePair(forceTable[k], sTableA[k], sTableB[k]);
#if COUNT_PAIRS
  if (gl_LocalInvocationID.x == 0) sPairs = 0u;
#endif
  barrier();
  for (uint s = gl_LocalInvocationID.x; s < uSpecies; s += gl_WorkGroupSize.x) {
    float r = 0.0;
    for (uint j = 0u; j < uSpecies; ++j) r = max(r, forceTable[s * uSpecies + j].y);
    sReach[s] = r;
  }
  barrier();

  const uint i = globalIndex();
  uint examined = 0u;
  if (i < uCount) {
    const vec4 pi = unpackPosition(positions[i]);
    const uint s = uint(pi.w);
    const uint row = s * uSpecies;
    vec2 force = -uCentralForce * pi.xy;
    ivec2 rx[2], ry[2];
    axisRanges(pi.x, sReach[s], 0, rx[0], rx[1]);
    axisRanges(pi.y, sReach[s], 1, ry[0], ry[1]);
    for (int a = 0; a < 2; ++a)
      for (int cy = ry[a].x; cy <= ry[a].y; ++cy)
        for (int b = 0; b < 2; ++b) {
          // Cells of one row in a range are adjacent: one contiguous run of particles.
          if (rx[b].x > rx[b].y) continue;
          const uint first = uint(cy) * uGridDims.x;
          const uint begin = cellStart[first + uint(rx[b].x)], end = cellStart[first + uint(rx[b].y) + 1u];
          examined += end - begin;
          for (uint j = begin; j < end; ++j) {
            const vec4 pj = unpackPosition(positions[j]);
            const uint k = row + uint(pj.w);
            if (j != i) force += pairForce(boxDelta(pi.xy, pj.xy), sTableA[k], sTableB[k]);
          }
        }
    accelerations[i] = force;
  }
#if COUNT_PAIRS
  atomicAdd(sPairs, examined);
  barrier();
  if (gl_LocalInvocationID.x == 0) groupPairs[groupIndex()] = sPairs;
#endif
}
