// Binding points of gl::DispatchGate's deciding kernels (common/dispatch_gate.glsl), shared by C++
// and GLSL: only #define lines.
#define DISPATCH_GATE_GROUPS 0  // uvec4 per recorded dispatch (x, y, z, 0)
#define DISPATCH_GATE_ARGS 1    // three uints per dispatch (glDispatchComputeIndirect)
