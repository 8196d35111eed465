#include "render/textures.h"

#include <cmath>

#include "io/assets.h"
#include "io/png.h"

namespace tidepool {

gl::Texture2D loadRepeatingTexture(const std::string& name) {
  const io::Image image = io::readPng(io::findAssetDir() / "textures" / name);
  const int levels = 1 + int(std::log2(std::max(image.width, image.height)));
  gl::Texture2D texture(image.width, image.height, GL_RGBA8, levels);
  texture.upload(GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  texture.generateMipmaps();
  texture.setWrap(GL_REPEAT);
  return texture;
}

}  // namespace tidepool
