// The deciding kernel's half of gl::DispatchGate (src/gl/dispatch_gate.h): the recorded group
// counts in, the indirect arguments out, zeros when the gated section should not run.
#ifndef COMMON_DISPATCH_GATE_GLSL
#define COMMON_DISPATCH_GATE_GLSL

#include "common/dispatch_gate_layout.glsl"

layout(std430, binding = DISPATCH_GATE_GROUPS) readonly buffer GateGroups { uvec4 gateGroups[]; };
layout(std430, binding = DISPATCH_GATE_ARGS) writeonly buffer GateArgs { uint gateArgs[]; };
uniform uint uGateDispatches;

// Every invocation of the (single) work group calls it with the same `open`.
void writeGateArgs(bool open) {
  for (uint k = gl_LocalInvocationIndex; k < uGateDispatches; k += gl_WorkGroupSize.x) {
    const uvec3 g = open ? gateGroups[k].xyz : uvec3(0u);
    gateArgs[3u * k] = g.x;
    gateArgs[3u * k + 1u] = g.y;
    gateArgs[3u * k + 2u] = g.z;
  }
}

#endif
