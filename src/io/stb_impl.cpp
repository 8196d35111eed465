// The stb implementations, compiled from the Debian libstb-dev headers into our library so the
// program does not need libstb at run time (the GPU machine has none).
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>
#include <stb_image_write.h>
