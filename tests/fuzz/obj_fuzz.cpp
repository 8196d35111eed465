// OBJ meshes (io/obj.h): parse, then what a dropped mesh goes through (bounds, closed check).
#include <cstdint>
#include <string>

#include "fuzz/fuzz_check.h"
#include "io/obj.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  tidepool::fuzz::expectParsedOrRefused("fuzz.obj", [&] {
    const tidepool::io::TriangleMesh mesh = tidepool::io::parseObj(text, "fuzz.obj");
    if (mesh.triangles.empty()) tidepool::fuzz::finding("a mesh without triangles was accepted");
    for (const glm::uvec3& t : mesh.triangles)
      for (int k = 0; k < 3; ++k)
        if (t[k] >= mesh.vertices.size()) tidepool::fuzz::finding("a triangle names a vertex that does not exist");
    (void)mesh.boundsMin();
    (void)tidepool::io::checkClosed(mesh).describe();
  });
  return 0;
}
