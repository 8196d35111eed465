// The stb implementations, compiled from the Debian libstb-dev headers into our library so the
// program does not need libstb at run time (the GPU machine has none). Dear ImGui's Debian build
// uses stb_truetype and stb_rect_pack from libstb, so those are compiled here too; the link uses
// --as-needed so libstb.so is then dropped.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_TRUETYPE_IMPLEMENTATION
#define STB_RECT_PACK_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>
#include <stb_image_write.h>
#include <stb_rect_pack.h>
#include <stb_truetype.h>

namespace tidepool::io {
// stb keeps the reason for its last failure until the next one (and has none before the first):
// png.cpp clears it before each call, so that the reason it reads is that call's.
void clearStbFailureReason() { stbi__g_failure_reason = nullptr; }
}  // namespace tidepool::io
