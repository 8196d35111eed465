// Binding points of the swarm renderer's own passes (src/render/swarm_renderer.cpp), shared by
// C++ and GLSL. Only #define lines: this file is valid in both languages. The model's buffers,
// the splat counters and the colour image keep the model's points (swarm/bindings.glsl).
#define SWARM_VIEW_ACCUM_UNIT 0  // sampler: high-quality accumulation (RGBA32F: colour sum, count)
