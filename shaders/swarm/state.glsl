// The swarm state buffer, one particle per slot: position in NDC, velocity in world units/s.
// STORAGE_FP16 = 1: {packHalf2x16(pos), packHalf2x16(vel)}, 8 bytes (also readable as a
// 4 x GL_HALF_FLOAT vertex attribute); 0: vec4(pos, vel), 16 bytes. Include after bindings.glsl.
#ifndef SWARM_STATE_GLSL
#define SWARM_STATE_GLSL

#if STORAGE_FP16
layout(std430, binding = SWARM_STATE_BINDING) buffer State { uvec2 particles[]; };

void loadParticle(uint i, out vec2 pos, out vec2 vel) {
  const uvec2 s = particles[i];
  pos = unpackHalf2x16(s.x);
  vel = unpackHalf2x16(s.y);
}
void storeParticle(uint i, vec2 pos, vec2 vel) { particles[i] = uvec2(packHalf2x16(pos), packHalf2x16(vel)); }
#else
layout(std430, binding = SWARM_STATE_BINDING) buffer State { vec4 particles[]; };

void loadParticle(uint i, out vec2 pos, out vec2 vel) {
  const vec4 s = particles[i];
  pos = s.xy;
  vel = s.zw;
}
void storeParticle(uint i, vec2 pos, vec2 vel) { particles[i] = vec4(pos, vel); }
#endif

#endif
