#version 430 core
// Fills a buffer's first uWords 32-bit words with uValue (gl::BufferOps::fill). Each invocation
// writes one uvec4; invocation 0 also writes the 0..3 words past the last whole uvec4. A shader
// instead of glClearBufferData, which one driver (NVIDIA 580 on an H100) runs at ~25 GB/s.
layout(local_size_x = 256) in;
#include "common/index.glsl"
#include "common/words_bindings.glsl"

layout(std430, binding = WORDS_FILL_TARGET) writeonly buffer Quads { uvec4 quads[]; };
layout(std430, binding = WORDS_FILL_TARGET) writeonly buffer Words { uint words[]; };

uniform uint uWords;
uniform uint uValue;

void main() {
  const uint i = globalIndex();
  const uint fullQuads = uWords / 4u;
  if (i < fullQuads) quads[i] = uvec4(uValue);
  if (i == 0u)
    for (uint w = fullQuads * 4u; w < uWords; ++w) words[w] = uValue;
}
