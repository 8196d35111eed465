#include "sim/particle_memory.h"

#include <algorithm>
#include <string>

#include "base/error.h"
#include "gl/gl.h"

namespace tidepool::sim {
namespace {
std::string mib(std::size_t bytes) { return std::to_string((bytes + (1 << 20) - 1) >> 20) + " MiB"; }
}  // namespace

void checkParticleMemory(const char* model, const char* particles, std::size_t capacity, std::size_t maxParticles,
                         std::size_t arrayBytes, std::size_t totalBytes) {
  const std::string head = std::string(model) + ": " + std::to_string(capacity) + " " + particles;
  if (capacity > maxParticles)
    throw Error(head + " requested, more than max_particles = " + std::to_string(maxParticles));
  const std::size_t bytes = std::max<std::size_t>(capacity, 1) * arrayBytes;
  GLint64 maxBlock = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
  if (bytes > std::size_t(maxBlock))
    throw Error(head + " need " + mib(bytes) + " per state array, more than this GPU's storage-buffer limit of " +
                mib(std::size_t(maxBlock)));
  if (GLAD_GL_NVX_gpu_memory_info) {
    GLint freeKb = 0;
    glGetIntegerv(GL_GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX, &freeKb);
    if (freeKb > 0 && totalBytes > std::size_t(freeKb) * 1024)
      throw Error(head + " need about " + mib(totalBytes) + ", but only " + mib(std::size_t(freeKb) * 1024) +
                  " of GPU memory are free");
  }
}

}  // namespace tidepool::sim
