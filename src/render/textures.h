// Textures from asset PNGs.
#pragma once

#include <string>

#include "gl/texture.h"

namespace tidepool {

// assets/textures/<name> as mipmapped RGBA8, repeating (floors, tiles). Throws Error.
gl::Texture2D loadRepeatingTexture(const std::string& name);

}  // namespace tidepool
