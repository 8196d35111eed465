// The one place GL is included from: the glad loader generated at build time for GL 4.3 core.
#pragma once

#include <glad/gl.h>

#include "base/error.h"

namespace tidepool::gl {

// A GL failure: a shader that does not compile, an incomplete framebuffer, a missing feature.
class GlError : public Error {
 public:
  using Error::Error;
};

}  // namespace tidepool::gl
