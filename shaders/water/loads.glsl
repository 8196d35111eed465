// The loads on the walls and the obstacles (src/sim/water/boundary_loads.h), for the kernels that
// measure what each particle's boundaries did to it: the fluid's predict and Δp (with
// BOUNDARY_LOADS), whose shares Δ of a particle's correction are momentum a boundary gave the
// water (F = −m ΣΔ / dt²), and the balls' loads.comp, whose shares are the accelerations a
// boundary gave a ball (F = −m Σa). Each kernel hands every invocation's shares to addLoads(); the
// work group adds them in a fixed order and adds the sums to its own partials, so the result does
// not depend on scheduling. The step's first kernel (with LOADS_FIRST) zeroes its group's partials
// (clearLoads) before adding; the walls' shares count only with LOADS_WALLS (a force probe on a
// wall). Slots: the six walls (−x, +x, −y, +y, −z, +z: a wall's share is along its normal), then
// one per obstacle, with the moment about its centre c_k.
// The including kernel defines LOADS_BINDING (the partials' storage block) and LOADS_GROUP_SIZE
// (its local size), and, before including this file,
//   void obstacleShare(uint k, out vec3 delta, out vec3 moment);  // this invocation's, for k
// and calls addLoads() from every invocation of the group (none may return before it).
#ifndef WATER_LOADS_GLSL
#define WATER_LOADS_GLSL

#define LOAD_WALL_SLOTS 6u
#define LOADS_TOUCHED_WALLS 31u  // the touched mask's bit for the walls (obstacles: bits 0-15)

// Coherent: the first kernel clears a group's partials and, with LOADS_WALLS, adds to them in the same
// dispatch from other invocations (memoryBarrierBuffer() and barrier() between).
layout(std430, binding = LOADS_BINDING) coherent buffer Loads { vec4 loads[]; };  // per group and slot: ΣΔ, Σ moment
uniform uint uLoadSlots;  // 6 + the obstacles

shared float sLoad[6][LOADS_GROUP_SIZE];
shared uint sTouched;

// Sums the group's six values per invocation into slot `slot` (walls: one value per wall), in a
// fixed order: 6 × LOAD_LANES invocations each add LOAD_RUN consecutive values of one, then six
// add those partial sums and add them to the group's partials.
#define LOAD_RUN 8u
#define LOAD_LANES (uint(LOADS_GROUP_SIZE) / LOAD_RUN)
shared float sLoadRun[6][LOAD_LANES];
void addGroup(uint slot, vec3 a, vec3 b, bool walls) {
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
    const uint base = groupIndex() * uLoadSlots;
    if (walls)
      loads[2u * (base + t)][t / 2u] += sum;  // wall t's push, along its axis
    else
      loads[2u * (base + slot) + t / 3u][t % 3u] += sum;  // ΣΔ (t < 3), Σ moment
  }
  barrier();  // sLoad is reused
}

// Zeroes the group's partials, an invocation per value: the step's first kernel, before it adds.
void clearLoads() {
  for (uint s = gl_LocalInvocationIndex; s < 2u * uLoadSlots; s += uint(LOADS_GROUP_SIZE))
    loads[2u * groupIndex() * uLoadSlots + s] = vec4(0.0);
}

// `wall`: this invocation's correction by the walls, per axis; `side` per axis: −1 the wall at
// the minimum, +1 at the maximum; `touched`: bit k for each obstacle k whose particles moved it.
void addLoads(vec3 wall, vec3 side, uint touched) {
  if (gl_LocalInvocationIndex == 0u) sTouched = 0u;
#ifdef LOADS_FIRST
  clearLoads();
  memoryBarrierBuffer();  // the clear seen by the invocations that add below
#endif
  barrier();
#ifdef LOADS_WALLS
  if (wall != vec3(0.0)) touched |= 1u << LOADS_TOUCHED_WALLS;
#endif
  if (touched != 0u) atomicOr(sTouched, touched);  // a bit mask: the same whatever the order
  barrier();
  const uint all = sTouched;
  if ((all & (1u << LOADS_TOUCHED_WALLS)) != 0u) {
    vec3 low = vec3(0.0), high = vec3(0.0);
    for (int k = 0; k < 3; ++k) {
      if (side[k] < 0.0)
        low[k] = wall[k];
      else
        high[k] = wall[k];
    }
    addGroup(0u, vec3(low.x, high.x, low.y), vec3(high.y, low.z, high.z), true);
  }
  for (uint k = 0u; k < LOADS_TOUCHED_WALLS; ++k) {
    if ((all & (1u << k)) == 0u) continue;
    vec3 delta = vec3(0.0), moment = vec3(0.0);
    if ((touched & (1u << k)) != 0u) obstacleShare(k, delta, moment);
    addGroup(LOAD_WALL_SLOTS + k, delta, moment, false);
  }
}

#endif
