// A compute round trip on the current context: shaders/selftest/fill.comp writes an SSBO that is
// read back and checked value by value. `tidepool info` runs it so a driver that reports GL 4.3
// but computes wrongly is caught before any simulation runs.
#pragma once

#include <string>

#include "gl/shader_library.h"

namespace tidepool::gl {

// Returns "" when every value matched, otherwise what went wrong.
std::string computeSelfTest(ShaderLibrary& shaders, unsigned count = 100003);

}  // namespace tidepool::gl
