// The optics of the water mode's surface (render/balls/compose.comp), each a textbook formula:
//   transmittance  Beer–Lambert per channel: T = exp(−σ d) with σ = −absorption · ln(colour), so
//                  that 1/absorption m of water passes `colour` and T(d1 + d2) = T(d1) T(d2)
//   schlick        Fresnel reflectance, Schlick's approximation: F0 + (1 − F0)(1 − cos θ)⁵
//   refracted      the eye's ray past the surface into water of index `ior` (Snell's law,
//                  sin θt = sin θi / ior); straight on where it would reflect totally
#ifndef RENDER_BALLS_WATER_OPTICS_GLSL
#define RENDER_BALLS_WATER_OPTICS_GLSL

vec3 transmittance(vec3 colour, float absorption, float thickness) {
  return pow(max(colour, vec3(1e-3)), vec3(absorption * thickness));
}

float schlick(float f0, float cosine) { return f0 + (1.0 - f0) * pow(1.0 - cosine, 5.0); }

vec3 refracted(vec3 incident, vec3 n, float ior) {  // incident, n: unit, n against the incident ray
  const vec3 r = refract(incident, n, 1.0 / ior);
  return r == vec3(0.0) ? incident : r;
}

#endif
