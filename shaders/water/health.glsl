// The divergence watch of the water, balls and fluid alike (src/sim/water/): particles whose
// position or velocity is NaN or infinite, the largest speed, and particles outside the walls
// (flagged). A model's health.comp includes it after common/health.glsl and calls it from checkHealth().
#ifndef WATER_HEALTH_GLSL
#define WATER_HEALTH_GLSL

uniform vec3 uWallMin;
uniform vec3 uWallMax;

void checkWaterParticle(vec3 p, vec3 v) {
  if (!isFinite(p) || !isFinite(v)) {
    healthNonFinite();
    return;
  }
  healthMax(length(v));
  if (any(lessThan(p, uWallMin - 1e-6)) || any(greaterThan(p, uWallMax + 1e-6))) healthFlag();
}

#endif
