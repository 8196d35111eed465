// Linear invocation index for 1D work spread over a 2D dispatch: Program::dispatchThreads()
// spills group counts beyond GL_MAX_COMPUTE_WORK_GROUP_COUNT.x (65535 minimum) into y.
// Include it after the layout(local_size_x = ...) in; line: gl_WorkGroupSize needs it.
#ifndef COMMON_INDEX_GLSL
#define COMMON_INDEX_GLSL

// Linear work-group index (kernels that work per group, e.g. one scan block per group).
uint groupIndex() { return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x; }

uint globalIndex() { return groupIndex() * gl_WorkGroupSize.x + gl_LocalInvocationID.x; }

#endif
