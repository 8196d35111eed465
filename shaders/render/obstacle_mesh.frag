#version 430 core
// Flat-shaded mesh, as water-webgpu draws its obstacles: colour · (0.2 + 0.8·(0.5 + 0.5·n·L)).
// The face normal comes from the screen-space derivatives of the view position, so it faces the
// camera whatever the file's winding.
in vec3 vView;

uniform vec3 uColor;      // linear RGB
uniform vec3 uLightView;  // towards the light, view space
out vec4 fragColor;

void main() {
  const vec3 n = normalize(cross(dFdx(vView), dFdy(vView)));
  fragColor = vec4(uColor * (0.2 + 0.8 * (0.5 + 0.5 * dot(n, uLightView))), 1.0);
}
