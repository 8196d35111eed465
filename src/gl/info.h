// What the current GL context offers: identity, compute limits, memory (where the driver says).
#pragma once

#include <cstdint>
#include <string>

namespace tidepool::gl {

struct GlInfo {
  std::string vendor, renderer, version, glsl;
  int major = 0, minor = 0;
  int maxWorkGroupSize[3] = {0, 0, 0};  // per dimension
  int maxWorkGroupCount[3] = {0, 0, 0};
  int maxWorkGroupInvocations = 0;
  int maxSharedMemoryBytes = 0;   // per work group
  std::int64_t maxSsboBytes = 0;  // GL_MAX_SHADER_STORAGE_BLOCK_SIZE
  int maxSsboBindings = 0;
  int maxTextureSize = 0;
  std::int64_t totalMemoryKb = -1;  // NVX_gpu_memory_info; -1 when unknown
  std::int64_t freeMemoryKb = -1;   // NVX_gpu_memory_info or ATI_meminfo; -1 when unknown
  bool timerQueries = false;        // GL_TIME_ELAPSED has counter bits
};

GlInfo queryInfo();                          // from the current context
std::string formatInfo(const GlInfo& info);  // the `tidepool info` table

}  // namespace tidepool::gl
