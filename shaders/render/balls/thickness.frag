#version 430 core
// Thickness pass (write mask B only, blend ONE + ONE, depth test against the scene's meshes,
// no depth write): adds the length of the eye ray inside every ball in front of the scene, so
// water before an obstacle is thin and water behind it adds nothing.
#include "render/balls/sphere.glsl"

layout(depth_greater) out float gl_FragDepth;

in vec3 vQuadPoint;
flat in vec3 vCentre;
flat in float vFoam;

uniform mat4 uProj;
uniform float uRadius;

layout(location = 0) out vec4 gbuffer;  // only B is written: thickness in metres

void main() {
  SphereHit hit;
  if (!intersectSphere(vQuadPoint, vCentre, uRadius, hit)) discard;
  gl_FragDepth = windowDepth(uProj, hit.point);
  gbuffer = vec4(0.0, 0.0, hit.chord, 0.0);
}
