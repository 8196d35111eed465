// Glossy ball: Lambert from the sun, sky ambient from above, Blinn-Phong highlight. Shared by
// sphere.frag (raster) and the ripples ray caster.
#ifndef RENDER_RIPPLES_BALL_SHADING_GLSL
#define RENDER_RIPPLES_BALL_SHADING_GLSL

// n: unit normal, v: unit direction to the eye, sunDir: unit, towards the sun.
vec3 ballColor(vec3 color, vec3 n, vec3 v, vec3 sunDir) {
  const float diffuse = max(dot(n, sunDir), 0.0);
  const float ambient = 0.25 + 0.2 * n.z;
  const float spec = pow(max(dot(n, normalize(sunDir + v)), 0.0), 80.0);
  return color * (ambient + 0.8 * diffuse) + vec3(0.5 * spec);
}

#endif
