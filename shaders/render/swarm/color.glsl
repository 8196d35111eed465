// Colour helpers of the swarm renderer.
#ifndef RENDER_SWARM_COLOR_GLSL
#define RENDER_SWARM_COLOR_GLSL

// The seed's fully saturated 6-segment hue ramp over [0, 1): red, yellow, green, cyan, blue, magenta.
vec3 hueRamp(float hue) {
  const float h = 6.0 * fract(hue);
  return clamp(vec3(abs(h - 3.0) - 1.0, 2.0 - abs(h - 2.0), 2.0 - abs(h - 4.0)), 0.0, 1.0);
}

#endif
