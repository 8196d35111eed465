#version 430 core
// Glossy ball: Lambert from the sun, sky ambient from above, Blinn-Phong highlight.
uniform vec3 uColor;   // linear RGB
uniform vec3 uSunDir;  // towards the sun
uniform vec3 uEye;
in vec3 vNormal;
in vec3 vWorld;
out vec4 fragColor;

void main() {
  const vec3 n = normalize(vNormal);
  const vec3 v = normalize(uEye - vWorld);
  const float diffuse = max(dot(n, uSunDir), 0.0);
  const float ambient = 0.25 + 0.2 * n.z;
  const float spec = pow(max(dot(n, normalize(uSunDir + v)), 0.0), 80.0);
  fragColor = vec4(uColor * (ambient + 0.8 * diffuse) + vec3(0.5 * spec), 1.0);
}
