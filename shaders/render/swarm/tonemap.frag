#version 430 core
// High-quality swarm composite: the accumulation image holds (sum of colours, count) per pixel
// in fp32, so nothing clips at 255 particles. Blending: brightness 1 - exp(-opacity * count)
// (one particle ~ opacity, saturating smoothly); opaque (uOpacity < 0): any particle shows fully.
#include "render/swarm/bindings.glsl"

layout(binding = SWARM_VIEW_ACCUM_UNIT) uniform sampler2D uAccum;
uniform float uOpacity;
out vec4 fragColor;

void main() {
  const vec4 sum = texelFetch(uAccum, ivec2(gl_FragCoord.xy), 0);
  const float count = sum.a;
  const vec3 mean = count > 0.0 ? sum.rgb / count : vec3(0.0);
  const float brightness = uOpacity < 0.0 ? step(0.5, count) : 1.0 - exp(-uOpacity * count);
  fragColor = vec4(mean * brightness, 1.0);
}
