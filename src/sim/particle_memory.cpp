#include "sim/particle_memory.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>

#include "base/error.h"
#include "gl/gl.h"
#include "gl/window.h"

namespace tidepool::sim {
namespace {
// The tighter of the current fit and `count` under `limit`.
void tighten(ParticleFit& fit, std::size_t count, const std::string& limit) {
  if (count < fit.count) fit = {count, limit};
}
}  // namespace

std::optional<std::size_t> freeGpuBytes() {
  if (GLAD_GL_NVX_gpu_memory_info) {
    GLint kb = 0;
    glGetIntegerv(GL_GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX, &kb);
    if (kb > 0) return std::size_t(kb) * 1024;
  }
  if (GLAD_GL_ATI_meminfo) {
    GLint kb[4] = {};  // free, largest free block, free auxiliary, largest auxiliary block (KiB)
    glGetIntegerv(GL_VBO_FREE_MEMORY_ATI, kb);
    if (kb[0] > 0) return std::size_t(kb[0]) * 1024;
  }
  return std::nullopt;
}

std::optional<std::size_t> freeHostBytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::size_t kb = 0;
  std::string unit;
  while (meminfo >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024;
  return std::nullopt;
}

ParticleFit particlesThatFit(const ParticleCost& cost, const char* particle) {
  // max_particles = 0: no cap of the scene's own, the device's limits alone.
  ParticleFit fit = cost.maxParticles > 0
                        ? ParticleFit{cost.maxParticles, "max_particles = " + std::to_string(cost.maxParticles)}
                        : ParticleFit{std::numeric_limits<std::size_t>::max(), "no limit known"};
  const std::size_t maxBlock = gl::storageBlockBytes();
  if (cost.arrayBytes)
    tighten(fit, maxBlock / cost.arrayBytes,
            "the storage-block limit, " + gl::sizeText(maxBlock) + " per array of " + std::to_string(cost.arrayBytes) +
                " B per " + particle);
  if (cost.windowedBytes)
    tighten(fit, gl::kMaxWindowedBufferBytes / cost.windowedBytes,
            "the windowed-array limit of " + std::to_string(gl::kMaxWindowedBufferBytes) + " bytes, at " +
                std::to_string(cost.windowedBytes) + " B per " + particle);
  if (const std::optional<std::size_t> gpu = freeGpuBytes(); gpu && cost.gpuBytes)
    tighten(fit, *gpu / cost.gpuBytes,
            "free GPU memory, " + gl::sizeText(*gpu) + " at " + std::to_string(cost.gpuBytes) + " B per " + particle);
  if (const std::optional<std::size_t> host = freeHostBytes(); host && cost.hostBytes)
    tighten(
        fit, *host / cost.hostBytes,
        "free host memory, " + gl::sizeText(*host) + " at " + std::to_string(cost.hostBytes) + " B per " + particle);
  return fit;
}

void checkParticleRequest(const char* model, const char* particle, double requested, const std::string& what,
                          const ParticleCost& cost, const std::string& fix) {
  const ParticleFit fit = particlesThatFit(cost, particle);
  if (!(requested > double(fit.count)) && std::isfinite(requested)) return;
  char count[64];
  std::snprintf(count, sizeof count, requested < 1e6 ? "%.0f" : "%.3g", requested);
  throw Error(std::string(model) + ": " + what + " would make about " + count + " " + particle + "s, but at most " +
              std::to_string(fit.count) + " fit (" + fit.limit + "): " + fix);
}

}  // namespace tidepool::sim
