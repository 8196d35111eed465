#include "io/png.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include "base/error.h"

namespace tidepool::io {

void writePng(const std::filesystem::path& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 || image.rgba.size() != std::size_t(image.width) * image.height * 4)
    throw Error("cannot write '" + path.string() + "': image is empty or its size does not match its pixels");
  if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4))
    throw Error("cannot write '" + path.string() + "': check that the folder exists and is writable");
}

Image readPng(const std::filesystem::path& path) {
  Image img;
  int channels = 0;
  stbi_uc* data = stbi_load(path.c_str(), &img.width, &img.height, &channels, 4);
  if (!data) throw Error("cannot read image '" + path.string() + "': " + stbi_failure_reason());
  img.rgba.assign(data, data + std::size_t(img.width) * img.height * 4);
  stbi_image_free(data);
  return img;
}

}  // namespace tidepool::io
