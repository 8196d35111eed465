// The most any input file may ask of the program: a hostile or mistaken file (a 2 GB "scene", a
// PNG header claiming 100000 x 100000 pixels, JSON nested 100000 deep) is refused with one line
// naming the file, the place and the limit, before anything large is allocated.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace tidepool::io {

constexpr std::uintmax_t kMiB = std::uintmax_t(1) << 20;

constexpr std::uintmax_t kMaxJsonFileBytes = 16 * kMiB;  // scenes, rules, sweep specs: a few KiB each
constexpr int kMaxJsonDepth = 64;                        // nested [ and {; scenes nest 4 deep
constexpr std::uintmax_t kMaxTextFileBytes = 64 * kMiB;  // CSV tables and other text
constexpr std::uintmax_t kMaxObjFileBytes = 256 * kMiB;  // ~4M triangles of plain "f a b c" lines
constexpr std::size_t kMaxObjVertices = 4'000'000;       // an obstacle is voxelized: far more is noise
constexpr std::size_t kMaxObjTriangles = 4'000'000;
constexpr std::uintmax_t kMaxPngFileBytes = 64 * kMiB;
constexpr int kMaxImageSide = 16384;                           // pixels, width or height (GL's usual limit)
constexpr std::size_t kMaxImagePixels = std::size_t(1) << 26;  // 64 Mpixel: 256 MiB as RGBA

// "16 MiB", "1.5 MiB", "512 bytes": a limit as a person reads it.
std::string byteSize(std::uintmax_t bytes);

}  // namespace tidepool::io
