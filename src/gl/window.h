// Arrays larger than one storage block. GL_MAX_SHADER_STORAGE_BLOCK_SIZE caps what one binding
// may see (16 MiB at GL 4.3's minimum, 128 MiB on llvmpipe, 2 GiB on an H100), not the size of a
// buffer: an array of particles larger than that is bound a window at a time (glBindBufferRange)
// and a pass over it runs one dispatch per window. Kernels take the window's first element as a
// uniform and index the bound range with the particle index less it (uFirst and uCount in
// shaders/balls/drift.comp):
//
//   for (const gl::Window& w : gl::windows(count, sizeof(glm::vec4))) {
//     gl::bindWindow(positions, BINDING, w, sizeof(glm::vec4));
//     kernel.dispatchThreads(w.count, {.first = GLuint(w.first), .count = GLuint(w.end())});
//   }
//
// Windows start at multiples of kWindowGrain elements, so offsets of 4- and 16-byte elements are
// multiples of 256 bytes, the largest GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT GL allows, and of
// 128-invocation work groups.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "gl/buffer.h"

namespace tidepool::gl {

// The storage-block limit in bytes: the driver's, or a lower one set by overrideStorageBlockBytes()
// or the environment variable TIDEPOOL_STORAGE_BLOCK_BYTES (to run a small GPU's windows on a big
// one; at least kMinStorageBlockBytes). Throws Error for an override that is not a byte count in range.
std::size_t storageBlockBytes();
// The largest buffer tidepool splits into windows: on the H100 and H200 (driver 580.159.04) a
// windowed array of balls ending at 4 GiB or past it read wrong, while one of 4.16 GB ran right
// (docs/PERFORMANCE.md, "Windowed arrays stop short of 4 GiB"), so a windowed array ends one window
// grain (4096 elements of 16 B) short of 4 GiB.
constexpr std::size_t kMaxWindowedBufferBytes = (std::size_t(4) << 30) - 65536;
constexpr std::size_t kWindowGrain = 4096;                        // elements
constexpr std::size_t kMinStorageBlockBytes = 16 * kWindowGrain;  // one grain of 16-byte elements
void overrideStorageBlockBytes(std::size_t bytes);                // 0: back to the driver's (and the environment's)

// "128 MiB", "256 KiB" (rounded up), "100 bytes": sizes next to the limit in error messages.
std::string sizeText(std::size_t bytes);

struct Window {
  std::size_t first = 0, count = 0;  // elements
  std::size_t end() const { return first + count; }
  bool operator==(const Window&) const = default;
};

// Elements of `elementBytes` that one window may hold: the limit's, rounded down to the grain
// (the whole limit's when it holds less than one grain).
std::size_t windowElements(std::size_t elementBytes);
// Windows covering [0, count): one ({0, count}) when the array fits a block, none for count 0.
std::vector<Window> windows(std::size_t count, std::size_t elementBytes);
bool needsWindows(std::size_t count, std::size_t elementBytes);  // more than one window
// The window from `first` (rounded down so that its offset is a multiple of
// GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT) to `end`.
Window alignedWindow(std::size_t first, std::size_t end, std::size_t elementBytes);
// Binds elements [w.first, w.end()) of `buffer` at `binding` (the whole buffer when w starts at 0
// and holds all of it).
void bindWindow(const Buffer& buffer, unsigned binding, const Window& w, std::size_t elementBytes);

}  // namespace tidepool::gl
