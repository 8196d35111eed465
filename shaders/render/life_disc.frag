#version 430 core
// Disc of radius uRadius world units with an analytic 1-pixel antialiased edge:
// alpha = clamp((radius - |o|)·pixelsPerUnit + 0.5, 0, 1), o the pixel centre's offset. Used when
// the radius covers at least one pixel.
in vec2 vOffset;
flat in vec3 vColor;
uniform float uRadius;
uniform float uPixelsPerUnit;
uniform float uExposure;
out vec4 fragColor;

void main() {
  const float alpha = clamp((uRadius - length(vOffset)) * uPixelsPerUnit + 0.5, 0.0, 1.0);
  if (alpha <= 0.0) discard;
  fragColor = vec4(vColor * uExposure, alpha);
}
