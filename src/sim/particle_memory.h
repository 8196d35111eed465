// The checks a particle model makes before allocating (balls, fluid): its max_particles key, the
// GL storage-block limit for one state array (GL_MAX_SHADER_STORAGE_BLOCK_SIZE: 16 MiB at GL 4.3's
// minimum, 128 MiB on llvmpipe, 2 GiB on an H100), the free GPU memory where the driver says
// (GL_NVX_gpu_memory_info, GL_ATI_meminfo) and the free host memory for the arrays built on the
// CPU. Each failure is one line naming the model, what asked, how many would fit, the limit that
// binds and the key to change:
//   balls: particles.radius = 0.0001 m would make about 2.1e+11 balls, but at most 8388608 fit
//   (the storage-block limit, 128 MiB per array of 16 B per ball): raise particles.radius or shrink the fill
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace tidepool::sim {

// What one particle costs, and the key that caps the count.
struct ParticleCost {
  std::size_t maxParticles = 0;   // the model's max_particles key (0: none, the device's limits alone)
  std::size_t arrayBytes = 16;    // of its largest GPU array bound whole (one storage block), per particle
  std::size_t windowedBytes = 0;  // of its largest array bound in windows (gl/window.h), per particle (0: none)
  std::size_t gpuBytes = 16;      // GPU bytes per particle in all
  std::size_t hostBytes = 0;      // host bytes per particle while the initial state is built (0: none)
};

// How many particles fit, and the limit that binds ("max_particles = 16777216", "the storage-block
// limit, 128 MiB per array of 16 B per ball", "free GPU memory, ...", "free host memory, ...").
struct ParticleFit {
  std::size_t count = 0;
  std::string limit;
};
ParticleFit particlesThatFit(const ParticleCost& cost, const char* particle);  // particle: "ball", "particle"

// Throws Error when `requested` (an estimate made before building anything, or the exact count)
// exceeds what fits: "<model>: <what> would make about <n> <particles>, but at most <fit> fit
// (<limit>): <fix>". `what` names the cause ("particles.radius = 0.0001 m", "7 balls requested").
void checkParticleRequest(const char* model, const char* particle, double requested, const std::string& what,
                          const ParticleCost& cost, const std::string& fix);

std::optional<std::size_t> freeGpuBytes();   // from GL_NVX_gpu_memory_info or GL_ATI_meminfo; nullopt: unknown
std::optional<std::size_t> freeHostBytes();  // MemAvailable of /proc/meminfo; nullopt: unknown

}  // namespace tidepool::sim
