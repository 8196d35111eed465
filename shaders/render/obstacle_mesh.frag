#version 430 core
// Obstacle surface: the obstacle colour lit like the balls (key light + ambient, a faint highlight).
in vec3 vNormal;

uniform vec3 uColor;      // linear RGB
uniform vec3 uLightView;  // towards the light, view space

out vec4 fragColor;

void main() {
  vec3 n = normalize(vNormal);
  if (!gl_FrontFacing) n = -n;  // the inside of a cup seen over its rim
  const float diffuse = max(dot(n, uLightView), 0.0);
  const float spec = pow(max(dot(reflect(-uLightView, n), vec3(0, 0, 1)), 0.0), 40.0);
  fragColor = vec4(uColor * (0.35 + 0.65 * diffuse) + vec3(0.15 * spec), 1.0);
}
