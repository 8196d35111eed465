// The particle-life box, centred on the origin: [-uBoxSize/2, uBoxSize/2] per axis (world
// units). With LOOPING the box is a torus and distances use the minimum image.
#ifndef LIFE_BOX_GLSL
#define LIFE_BOX_GLSL

uniform vec2 uBoxSize;  // simulationSize: width, height (world units)

// Shortest vector from a to b (minimum image on the torus).
vec2 boxDelta(vec2 a, vec2 b) {
  vec2 d = b - a;
#if LOOPING
  d -= uBoxSize * round(d / uBoxSize);
#endif
  return d;
}

#endif
