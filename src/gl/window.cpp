#include "gl/window.h"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "base/error.h"
#include "gl/gl.h"

namespace tidepool::gl {
namespace {
std::size_t g_override = 0;

std::size_t checkedLimit(std::size_t bytes, const std::string& what) {
  if (bytes < kMinStorageBlockBytes)
    throw Error(what + " = " + std::to_string(bytes) +
                " bytes is below the smallest storage-block limit tidepool runs with, " +
                std::to_string(kMinStorageBlockBytes) + " bytes");
  return bytes;
}

std::size_t parseEnvironmentLimit() {
  const char* text = std::getenv("TIDEPOOL_STORAGE_BLOCK_BYTES");
  if (!text || !*text) return 0;
  char* end = nullptr;
  const unsigned long long bytes = std::strtoull(text, &end, 10);
  if (*end != '\0' || text[0] == '-')
    throw Error(std::string("TIDEPOOL_STORAGE_BLOCK_BYTES = '") + text + "' is not a byte count");
  return checkedLimit(std::size_t(bytes), "TIDEPOOL_STORAGE_BLOCK_BYTES");
}

// Read once per process (the windows ask several times a step); a bad value fails every time.
std::size_t environmentLimit() {
  struct Parsed {
    std::size_t bytes = 0;
    std::string error;
  };
  static const Parsed parsed = [] {
    try {
      return Parsed{parseEnvironmentLimit(), ""};
    } catch (const Error& e) {
      return Parsed{0, e.what()};
    }
  }();
  if (!parsed.error.empty()) throw Error(parsed.error);
  return parsed.bytes;
}
}  // namespace

std::size_t storageBlockBytes() {
  static const std::size_t driver = [] {  // one query per process
    GLint64 bytes = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &bytes);
    return std::size_t(std::max<GLint64>(bytes, 0));
  }();
  std::size_t limit = driver;
  const std::size_t lower = g_override ? g_override : environmentLimit();
  if (lower) limit = std::min(limit, lower);
  return limit;
}

void overrideStorageBlockBytes(std::size_t bytes) {
  g_override = bytes ? checkedLimit(bytes, "storage-block limit override") : 0;
}

std::size_t windowElements(std::size_t elementBytes) {
  const std::size_t fit = storageBlockBytes() / elementBytes;
  return fit >= kWindowGrain ? fit / kWindowGrain * kWindowGrain : fit;
}

std::vector<Window> windows(std::size_t count, std::size_t elementBytes) {
  std::vector<Window> out;
  if (count * elementBytes <= storageBlockBytes()) {
    if (count) out.push_back({0, count});
    return out;
  }
  const std::size_t step = windowElements(elementBytes);
  if (step == 0)
    throw Error("an element of " + std::to_string(elementBytes) + " bytes exceeds the storage-block limit");
  for (std::size_t first = 0; first < count; first += step) out.push_back({first, std::min(step, count - first)});
  return out;
}

bool needsWindows(std::size_t count, std::size_t elementBytes) { return count * elementBytes > storageBlockBytes(); }

std::string sizeText(std::size_t bytes) {
  if (bytes >= (std::size_t(1) << 20)) return std::to_string((bytes + (1 << 20) - 1) >> 20) + " MiB";
  if (bytes >= 1024) return std::to_string((bytes + 1023) >> 10) + " KiB";
  return std::to_string(bytes) + " bytes";
}

Window alignedWindow(std::size_t first, std::size_t end, std::size_t elementBytes) {
  static const std::size_t alignment = [] {  // one query per process
    GLint v = 0;
    glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &v);
    return std::size_t(std::max(v, 1));
  }();
  std::size_t start = first;
  while ((start * elementBytes) % alignment != 0) --start;  // at most alignment steps: 0 is aligned
  return {start, end - start};
}

void bindWindow(const Buffer& buffer, unsigned binding, const Window& w, std::size_t elementBytes) {
  if (w.first == 0 && w.count * elementBytes >= buffer.size() && buffer.size() <= storageBlockBytes())
    buffer.bindBase(GL_SHADER_STORAGE_BUFFER, binding);
  else
    buffer.bindRange(GL_SHADER_STORAGE_BUFFER, binding, w.first * elementBytes, w.count * elementBytes);
}

}  // namespace tidepool::gl
