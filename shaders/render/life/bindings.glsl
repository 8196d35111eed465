// Sampler units of the life view's compose pass (src/render/life_view.cpp), shared by C++ and
// GLSL. Only #define lines: this file is valid in both languages. The particle passes read the
// model's buffers at the model's binding points (life/bindings.glsl).
#define LIFE_VIEW_HDR_UNIT 0         // the HDR image the particles were added into (RGBA16F)
#define LIFE_VIEW_BLUE_NOISE_UNIT 1  // blue-noise dither thresholds (R32F), tiled by pixel
