// Blue-noise threshold maps made by our own code: Ulichney's void-and-cluster (1993) on a torus
// with a Gaussian energy (sigma 1.5 pixels). Deterministic: the same size and seed give the same
// map on every machine. Used for dithering HDR images to 8 bits without banding.
#pragma once

#include <cstdint>
#include <vector>

#include "gl/texture.h"

namespace tidepool {

// size x size thresholds in (0, 1): pixel k holds (rank + 0.5) / size^2, each rank once.
std::vector<float> voidAndCluster(int size, std::uint32_t seed = 1);

// The 64x64 map as an R32F texture, nearest filtering (the map is computed once per process).
gl::Texture2D makeBlueNoiseTexture();

}  // namespace tidepool
