// Particle-life rules JSON (sim/life/life_rules.h). Rules that load must round trip through the
// JSON writer and the share code unchanged.
#include <cstdint>
#include <string>

#include "fuzz/fuzz_check.h"
#include "io/json.h"
#include "sim/life/life_rules.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tidepool;
  const std::string text(reinterpret_cast<const char*>(data), size);
  fuzz::expectParsedOrRefused("fuzz.json", [&] {
    const life::Rules rules = life::rulesFromJson(io::parseJson(text, "fuzz.json"), "fuzz.json");
    if (!(life::rulesFromJson(life::rulesToJson(rules), "again") == rules))
      fuzz::finding("rules changed through rulesToJson -> rulesFromJson");
    if (!(life::decodeShareCode(life::encodeShareCode(rules)) == rules))
      fuzz::finding("rules changed through their share code");
  });
  return 0;
}
