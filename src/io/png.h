// PNG files through stb (libstb-dev headers). Pixels are 8-bit RGBA, top row first.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace tidepool::io {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4, top row first
};

void writePng(const std::filesystem::path& path, const Image& image);  // throws Error
Image readPng(const std::filesystem::path& path);                      // throws Error; converts to RGBA

}  // namespace tidepool::io
