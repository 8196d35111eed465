#version 430 core
// Image colouring of the swarm: each particle takes the colour of the image (stretched over the
// NDC box, top row at y = +1) at its current position, bilinear and clamped; run after a reset,
// so the colour marks where the particle started. Stored as packUnorm4x8 (a normalized
// 4 x GL_UNSIGNED_BYTE vertex attribute).
layout(local_size_x = 256) in;
#include "common/index.glsl"
#include "swarm/bindings.glsl"
#include "swarm/state.glsl"

layout(std430, binding = SWARM_COLOR_BINDING) buffer Colors { uint colors[]; };
layout(binding = SWARM_IMAGE_UNIT) uniform sampler2D uImage;
uniform uint uCount;

void main() {
  const uint i = globalIndex();
  if (i >= uCount) return;
  vec2 pos, vel;
  loadParticle(i, pos, vel);
  const vec2 uv = vec2(0.5 + 0.5 * pos.x, 0.5 - 0.5 * pos.y);
  colors[i] = packUnorm4x8(textureLod(uImage, uv, 0.0));
}
