// Scene files (scene/scene.h): JSON text -> the header's keys -> the model's typed params ->
// method auto. Reaches no GL: building the stage is what needs a context, parsing does not.
#include <cstdint>
#include <string>

#include "fuzz/fuzz_check.h"
#include "io/json.h"
#include "scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  tidepool::fuzz::expectParsedOrRefused("fuzz.json", [&] {
    const tidepool::io::Json json = tidepool::io::parseJson(text, "fuzz.json");
    (void)tidepool::parseScene(json, "fuzz.json");
  });
  return 0;
}
