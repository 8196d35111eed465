#version 430 core
// Attractor markers: one point per attractor, from a uniform array (no buffers).
#include "swarm/bindings.glsl"
uniform vec4 uMarkers[SWARM_MAX_ATTRACTORS];  // xy: NDC, z: strength
out float vStrength;

void main() {
  gl_Position = vec4(uMarkers[gl_VertexID].xy, 0.0, 1.0);
  gl_PointSize = 13.0;
  vStrength = uMarkers[gl_VertexID].z;
}
