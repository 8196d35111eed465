// Where the program's data lives: scenes, textures, meshes and rules under one assets/ folder.
#pragma once

#include <filesystem>

namespace tidepool::io {

// Folder of assets (scenes, textures, meshes, rules): $TIDEPOOL_ASSET_DIR, next to the
// executable, or the source tree. Throws Error when none is found.
std::filesystem::path findAssetDir();

}  // namespace tidepool::io
