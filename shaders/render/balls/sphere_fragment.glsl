// Fragment side of the sphere impostors (gbuffer.vert's quads, sphere.glsl), shared by the
// G-buffer and thickness passes: the eye ray through the fragment meets its ball, and the
// fragment's depth moves back onto the sphere (it only grows: layout(depth_greater) keeps early
// depth rejection).
#include "render/balls/sphere.glsl"

layout(depth_greater) out float gl_FragDepth;

in vec3 vQuadPoint;
flat in vec3 vCentre;
flat in float vFoam;

uniform mat4 uProj;
uniform float uRadius;

// The ball's surface under this fragment, with gl_FragDepth set to its window depth; a fragment
// whose ray misses the ball is discarded.
SphereHit sphereFragment() {
  SphereHit hit;
  if (!intersectSphere(vQuadPoint, vCentre, uRadius, isOrthographic(uProj), hit)) discard;
  gl_FragDepth = windowDepth(uProj, hit.point);
  return hit;
}
