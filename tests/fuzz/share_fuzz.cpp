// Particle-life share codes (sim/life/life_share.cpp). The first byte picks what the rest is
// (the seeds in corpus/share: "#" + a code, or a zero byte + packed rules):
// odd, the code as pasted text; even, the packed rules themselves, which this target seals with
// their CRC-32 and base64url so that mutations reach the field reader behind the checksum.
// Rules that decode must encode and decode again unchanged.
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz/fuzz_check.h"
#include "io/checkpoint_file.h"  // io::crc32
#include "sim/life/life_rules.h"

namespace {

std::string sealed(std::vector<std::uint8_t> b) {
  static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
  const std::uint32_t crc = tidepool::io::crc32(b);
  for (int i = 0; i < 4; ++i) b.push_back(std::uint8_t(crc >> (8 * i)));
  std::string out;
  std::uint32_t acc = 0;
  int bits = 0;
  for (std::uint8_t byte : b) {
    acc = (acc << 8) | byte;
    bits += 8;
    while (bits >= 6) out += alphabet[(acc >> (bits -= 6)) & 63];
  }
  if (bits > 0) out += alphabet[(acc << (6 - bits)) & 63];
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tidepool;
  if (size == 0) return 0;
  const std::string code = data[0] & 1 ? std::string(reinterpret_cast<const char*>(data + 1), size - 1)
                                       : sealed(std::vector<std::uint8_t>(data + 1, data + size));
  fuzz::expectParsedOrRefused("share code", [&] {
    const life::Rules rules = life::decodeShareCode(code);
    if (!(life::decodeShareCode(life::encodeShareCode(rules)) == rules))
      fuzz::finding("rules changed through encode -> decode");
  });
  return 0;
}
