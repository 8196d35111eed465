// The particle-life pair force, shared by forces.comp and the brute-force reference. The table
// entry (strength, radius, |collisionStrength|, collisionRadius) is pre-shaped per work group
// into two values so that the common case — a candidate beyond the radius — costs one dot
// product and no square root or division:
//   a = (strength, strength / R, R^2, collisionStrength), b = 1 / Rc (no collision when Rc = 0:
//   a.w = b = 0, rather than relying on 1/0 = inf, which GLSL does not promise)
//   F = (strength·(1 - d/R) - collisionStrength·max(0, 1 - d/Rc)) · r/d   for 0 < d < R
#ifndef LIFE_PAIR_FORCE_GLSL
#define LIFE_PAIR_FORCE_GLSL

void shapePair(vec4 entry, out vec4 a, out float b) {
  const bool collides = entry.w > 0.0;
  a = vec4(entry.x, entry.y > 0.0 ? entry.x / entry.y : 0.0, entry.y * entry.y, collides ? entry.z : 0.0);
  b = collides ? 1.0 / entry.w : 0.0;
}

// Force on a particle from a neighbour at offset r (minimum image already applied).
vec2 pairForce(vec2 r, vec4 a, float b) {
  const float d2 = dot(r, r);
  if (!(d2 > 0.0 && d2 < a.z)) return vec2(0.0);
  const float d = sqrt(d2);
  const float magnitude = a.x - a.y * d - a.w * max(0.0, 1.0 - d * b);
  return magnitude * (r / d);
}

#endif
