// The box walls: a contact with a fixed (possibly moving) body for the force laws, the CUDA
// sample's clamp-and-bounce for CONTACT_CUDA, and always a final clamp so that no ball ever
// leaves the domain.
#ifndef BALLS_WALLS_GLSL
#define BALLS_WALLS_GLSL

uniform vec3 uWallMin;      // current wall positions, m
uniform vec3 uWallMax;
uniform vec3 uWallMinVel;   // wall velocities (the piston), m/s
uniform vec3 uWallMaxVel;
uniform float uBoundaryDamping;  // CUDA sample: velocity factor at a wall (−0.5)

#ifdef BALLS_CONTACT_GLSL
vec3 wallsAccel(vec3 p, vec3 v) {
  vec3 a = vec3(0.0);
  for (int k = 0; k < 3; ++k) {
    vec3 axis = vec3(0.0);
    axis[k] = 1.0;
    const float below = uWallMin[k] + uRadius - p[k];
    if (below > 0.0) a += wallAccel(axis, below, v - uWallMinVel);
    const float above = p[k] - (uWallMax[k] - uRadius);
    if (above > 0.0) a += wallAccel(-axis, above, v - uWallMaxVel);
  }
  return a;
}
#endif

// (uRadius is declared by the including kernel.)
void confineToDomain(inout vec3 x, inout vec3 v) {
#ifdef CONTACT_CUDA
  for (int k = 0; k < 3; ++k) {
    if (x[k] > uWallMax[k] - uRadius) {
      x[k] = uWallMax[k] - uRadius;
      v[k] *= uBoundaryDamping;
    }
    if (x[k] < uWallMin[k] + uRadius) {
      x[k] = uWallMin[k] + uRadius;
      v[k] *= uBoundaryDamping;
    }
  }
#endif
  x = clamp(x, uWallMin, uWallMax);  // never outside, whatever the time step
}

#endif
