#version 430 core
// Copies uWords 32-bit words from WORDS_COPY_SRC to WORDS_COPY_DST (gl::BufferOps::copy): one
// uvec4 per invocation, invocation 0 also copies the 0..3 trailing words. Also the benchmarks'
// bandwidth reference: a plain coalesced copy run by the shader cores (glCopyBufferSubData may
// run on a copy engine, ~170 GB/s on an H100).
layout(local_size_x = 256) in;
#include "common/index.glsl"
#include "common/words_bindings.glsl"

layout(std430, binding = WORDS_COPY_SRC) readonly buffer SrcQuads { uvec4 srcQuads[]; };
layout(std430, binding = WORDS_COPY_SRC) readonly buffer SrcWords { uint srcWords[]; };
layout(std430, binding = WORDS_COPY_DST) writeonly buffer DstQuads { uvec4 dstQuads[]; };
layout(std430, binding = WORDS_COPY_DST) writeonly buffer DstWords { uint dstWords[]; };

uniform uint uWords;

void main() {
  const uint i = globalIndex();
  const uint fullQuads = uWords / 4u;
  if (i < fullQuads) dstQuads[i] = srcQuads[i];
  if (i == 0u)
    for (uint w = fullQuads * 4u; w < uWords; ++w) dstWords[w] = srcWords[w];
}
