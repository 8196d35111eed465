#version 430 core
// A thin ring: white for attractive, red for repulsive attractors.
in float vStrength;
out vec4 fragColor;

void main() {
  const float r = length(2.0 * gl_PointCoord - 1.0);
  if (r > 1.0 || r < 0.7) discard;
  fragColor = vStrength >= 0.0 ? vec4(1.0, 1.0, 1.0, 0.7) : vec4(1.0, 0.3, 0.25, 0.8);
}
