// The checks a particle model makes before allocating (balls, fluid): its max_particles key, the
// GL storage-block limit for one state array, and the free GPU memory where the driver says
// (GL_NVX_gpu_memory_info). Each failure is an Error naming the model, the numbers and the limit.
#pragma once

#include <cstddef>

namespace tidepool::sim {

// `capacity` particles of `arrayBytes` each per state array (a vec4: 16), `totalBytes` in all.
void checkParticleMemory(const char* model, const char* particles, std::size_t capacity, std::size_t maxParticles,
                         std::size_t arrayBytes, std::size_t totalBytes);

}  // namespace tidepool::sim
