#version 430 core
// Copies uWords 32-bit words from binding 0 to binding 1 (gl::BufferOps::copy): one uvec4 per
// invocation, invocation 0 also copies the 0..3 trailing words. Also the benchmarks' bandwidth
// reference: a plain coalesced copy run by the shader cores (glCopyBufferSubData may run on a
// copy engine, ~170 GB/s on an H100).
layout(local_size_x = 256) in;
#include "common/index.glsl"

layout(std430, binding = 0) readonly buffer SrcQuads { uvec4 srcQuads[]; };
layout(std430, binding = 0) readonly buffer SrcWords { uint srcWords[]; };
layout(std430, binding = 1) writeonly buffer DstQuads { uvec4 dstQuads[]; };
layout(std430, binding = 1) writeonly buffer DstWords { uint dstWords[]; };

uniform uint uWords;

void main() {
  const uint i = globalIndex();
  const uint fullQuads = uWords / 4u;
  if (i < fullQuads) dstQuads[i] = srcQuads[i];
  if (i == 0u)
    for (uint w = fullQuads * 4u; w < uWords; ++w) dstWords[w] = srcWords[w];
}
