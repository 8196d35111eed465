#version 430 core
// Thickness pass (write mask B only, blend ONE + ONE, depth test against the scene's meshes,
// no depth write): adds the length of the eye ray inside every ball in front of the scene, so
// water before an obstacle is thin and water behind it adds nothing.
#include "render/balls/sphere_fragment.glsl"

layout(location = 0) out vec4 gbuffer;  // only B is written: thickness in metres

void main() { gbuffer = vec4(0.0, 0.0, sphereFragment().chord, 0.0); }
