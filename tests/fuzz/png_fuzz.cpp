// PNG images (io/png.h): the bytes of a file, decoded to RGBA within the image limits.
#include <cstdint>
#include <string>

#include "fuzz/fuzz_check.h"
#include "io/limits.h"
#include "io/png.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tidepool::fuzz::expectParsedOrRefused("fuzz.png", [&] {
    const tidepool::io::Image img = tidepool::io::decodePng({data, size}, "fuzz.png");
    if (img.width <= 0 || img.height <= 0 || img.width > tidepool::io::kMaxImageSide ||
        img.height > tidepool::io::kMaxImageSide ||
        img.rgba.size() != std::size_t(img.width) * std::size_t(img.height) * 4)
      tidepool::fuzz::finding("decoded image of " + std::to_string(img.width) + " x " + std::to_string(img.height) +
                              " with " + std::to_string(img.rgba.size()) + " bytes");
  });
  return 0;
}
