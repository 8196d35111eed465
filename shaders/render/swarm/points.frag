#version 430 core
// Swarm point or round sprite. Accumulating (high quality): rgb and a count of 1 per fragment.
in vec3 vColor;
uniform int uRound;        // 1: discard outside the inscribed circle (sprites of 3+ px)
uniform float uOpacity;    // alpha for additive blending (1 when opaque)
uniform int uAccumulate;
out vec4 fragColor;

void main() {
  if (uRound != 0 && dot(2.0 * gl_PointCoord - 1.0, 2.0 * gl_PointCoord - 1.0) > 1.0) discard;
  fragColor = uAccumulate != 0 ? vec4(vColor, 1.0) : vec4(vColor, uOpacity);
}
