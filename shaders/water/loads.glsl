// The loads on the walls (src/sim/water/boundary_loads.h), for the kernels that measure what each
// particle's walls did to it while a wall is probed (LOADS_WALLS): the fluid's predict and Δp,
// whose shares Δ of a particle's correction are momentum a wall gave the water (F = −m ΣΔ / dt²),
// and the balls' loads.comp, whose shares are the accelerations a wall gave a ball (F = −m Σa).
// Each kernel hands every invocation's shares to addLoads(); the work group adds them in a fixed
// order and adds the sums to its own partials, so the result does not depend on scheduling. The
// step's first kernel (with LOADS_FIRST) zeroes its group's partials before adding. A group's
// partials are two vec4: the pushes on the walls −x, +x, −y, +y and −z, +z, each along its axis.
// (The obstacles' loads are summed from the obstacles' side: water/obstacle_loads.glsl.)
// The including kernel defines LOADS_BINDING (the partials' storage block) and LOADS_GROUP_SIZE
// (its local size), and calls addLoads() from every invocation of the group (none may return
// before it).
#ifndef WATER_LOADS_GLSL
#define WATER_LOADS_GLSL

// Coherent: the first kernel clears a group's partials and adds to them in the same dispatch
// from other invocations (memoryBarrierBuffer() and barrier() between).
layout(std430, binding = LOADS_BINDING) coherent buffer Loads { vec4 loads[]; };  // two per work group

shared float sLoad[6][LOADS_GROUP_SIZE];
shared uint sTouched;

// Sums the group's six values per invocation in a fixed order: 6 × LOAD_LANES invocations each
// add LOAD_RUN consecutive values of one, then six add those partial sums to the group's partials.
#define LOAD_RUN 8u
#define LOAD_LANES (uint(LOADS_GROUP_SIZE) / LOAD_RUN)
shared float sLoadRun[6][LOAD_LANES];
void addGroup(vec3 a, vec3 b) {
  const uint t = gl_LocalInvocationIndex;
  sLoad[0][t] = a.x, sLoad[1][t] = a.y, sLoad[2][t] = a.z;
  sLoad[3][t] = b.x, sLoad[4][t] = b.y, sLoad[5][t] = b.z;
  barrier();
  if (t < 6u * LOAD_LANES) {
    const uint v = t / LOAD_LANES, first = (t % LOAD_LANES) * LOAD_RUN;
    float sum = 0.0;
    for (uint i = 0u; i < LOAD_RUN; ++i) sum += sLoad[v][first + i];
    sLoadRun[v][t % LOAD_LANES] = sum;
  }
  barrier();
  if (t < 6u) {
    float sum = 0.0;
    for (uint l = 0u; l < LOAD_LANES; ++l) sum += sLoadRun[t][l];
    loads[2u * groupIndex() + t / 4u][t % 4u] += sum;  // wall t's push, along its axis
  }
}

// `wall`: this invocation's correction by the walls, per axis; `side` per axis: −1 the wall at
// the minimum, +1 at the maximum.
void addLoads(vec3 wall, vec3 side) {
  const uint t = gl_LocalInvocationIndex;
  if (t == 0u) sTouched = 0u;
#ifdef LOADS_FIRST
  if (t < 2u) loads[2u * groupIndex() + t] = vec4(0.0);  // zeroed before any invocation adds
  memoryBarrierBuffer();
#endif
  barrier();
  if (wall != vec3(0.0)) atomicOr(sTouched, 1u);  // a flag: the same whatever the order
  barrier();
  if (sTouched == 0u) return;  // uniform in the group: no wall touched
  vec3 low = vec3(0.0), high = vec3(0.0);
  for (int k = 0; k < 3; ++k) {
    if (side[k] < 0.0)
      low[k] = wall[k];
    else
      high[k] = wall[k];
  }
  addGroup(vec3(low.x, high.x, low.y), vec3(high.y, low.z, high.z));
}

#endif
