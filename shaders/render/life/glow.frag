#version 430 core
// Glow: a Gaussian halo over the quad, alpha = intensity·exp(-6 |o|^2), o = offset / half-size
// in [-1, 1]^2 (the article: half-size 12 units, intensity 1/64). Added into the HDR image.
in vec2 vOffset;
flat in vec3 vColor;
uniform float uHalfSize;
uniform float uGlowIntensity;
uniform float uExposure;
out vec4 fragColor;

void main() {
  const vec2 o = vOffset / uHalfSize;
  fragColor = vec4(vColor * uExposure, uGlowIntensity * exp(-6.0 * dot(o, o)));
}
