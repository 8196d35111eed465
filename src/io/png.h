// PNG files through stb (libstb-dev headers). Pixels are 8-bit RGBA, top row first.
// Reading refuses files over kMaxPngFileBytes and images over kMaxImageSide per side or
// kMaxImagePixels in all (io/limits.h) from the header, before decoding.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace tidepool::io {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4, top row first
};

void writePng(const std::filesystem::path& path, const Image& image);  // throws Error
Image readPng(const std::filesystem::path& path);                      // throws Error; converts to RGBA
// The bytes of a PNG file; `name` starts every error ("tiles.png: ..."). Throws Error.
Image decodePng(std::span<const std::uint8_t> bytes, const std::string& name);

}  // namespace tidepool::io
