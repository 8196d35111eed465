// Bad input gets one clear line naming what is wrong and a non-zero exit, never a crash.
#include <gtest/gtest.h>

#include "support/gl_test.h"
#include "support/one_line_error.h"

using namespace tidepool;
using test::expectOneLineError;
using test::runTidepool;

TEST(BadInput, MissingSceneFile) {
  expectOneLineError({"render", "/nonexistent/scene.json", "--out", "/tmp/x"},
                     "file not found: '/nonexistent/scene.json'", 1);
  expectOneLineError({"render", "nosuchscene", "--out", "/tmp/x"}, "scene 'nosuchscene' not found", 1);
}

TEST(BadInput, MalformedJsonNamesLineAndColumn) {
  test::TempDir dir;
  dir.write("bad.json", "{\n  \"model\": \"blank\",\n  \"params\": {\"color\": [1, 0, 0}\n}\n");
  expectOneLineError({"render", (dir / "bad.json").string(), "--out", (dir / "o").string()},
                     (dir / "bad.json").string() + ":3:", 1);
  auto r = runTidepool({"render", (dir / "bad.json").string(), "--out", (dir / "o").string()});
  EXPECT_NE(r.err.find("malformed JSON"), std::string::npos);
}

TEST(BadInput, InvalidSceneValues) {
  test::TempDir dir;
  dir.write("range.json", R"({"model": "blank", "params": {"color": [2, 0, 0]}})");
  expectOneLineError({"render", (dir / "range.json").string(), "--out", (dir / "o").string()},
                     "params.color[0] = 2 is out of range [0, 1]", 1);
  dir.write("model.json", R"({"model": "nope"})");
  expectOneLineError({"render", (dir / "model.json").string(), "--out", (dir / "o").string()}, "is not a model", 1);
}

TEST(BadInput, UnknownSubcommandOrOption) {
  expectOneLineError({"frobnicate"}, "unknown subcommand 'frobnicate'", 2);
  expectOneLineError({"render", "blank", "--colour", "red"}, "--colour", 2);
  expectOneLineError({}, "subcommand is required", 2);
  expectOneLineError({"render", "blank", "--frames", "0", "--out", "/tmp/x"}, "--frames", 2);
  expectOneLineError({"info", "--backend", "vulkan"}, "--backend", 2);
  expectOneLineError({"render", "blank", "--size", "12x", "--out", "/tmp/x"}, "--size '12x' is not WIDTHxHEIGHT", 1);
}

TEST(BadInput, ObstacleMeshMissingMalformedOrOpen) {
  test::TempDir dir;
  auto scene = [&](const std::string& name, const std::string& mesh) {
    dir.write(name, R"({"model": "balls", "params": {"particles": {"fill": "none"},
                        "obstacles": [{"shape": "mesh", "mesh": ")" +
                        mesh + R"("}]}})");
    return std::vector<std::string>{"render", (dir / name).string(), "--frames", "1", "--out", (dir / "o").string()};
  };
  expectOneLineError(scene("missing.json", "nosuchmesh"),
                     (dir / "missing.json").string() +
                         ": params: obstacles[0]: mesh 'nosuchmesh' not found: neither a file nor a name in "
                         "assets/meshes (known: "
                         "blob, cube, paddle-wheel, torus)",
                     1);
  dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n");
  expectOneLineError(scene("bad.json", (dir / "bad.obj").string()),
                     (dir / "bad.obj").string() + ":3: bad number 'zero' in vertex", 1);
  dir.write("open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n");
  expectOneLineError(scene("open.json", (dir / "open.obj").string()),
                     "is not closed: 3 edges belong to one triangle only (a hole); the first at vertices 2-3: a solid "
                     "fill needs a closed mesh; fix the mesh or make the obstacle a shell",
                     1);
  dir.write("list.json", R"({"model": "balls", "params": {"obstacles": [{}, {"size": [500, 0.1, 0.1]}]}})");
  expectOneLineError({"render", (dir / "list.json").string(), "--frames", "1", "--out", (dir / "o").string()},
                     (dir / "list.json").string() + ": params.obstacles[1].size[0] = 500 is out of range [0, 100]", 1);
}

TEST(BadInput, UnreadableShaderDirectory) {
  expectOneLineError({"render", "blank", "--frames", "1", "--out", "/tmp/tidepool-x"},
                     "shader directory '/nonexistent/shaders' (from TIDEPOOL_SHADER_DIR) is not a readable directory",
                     1, {"TIDEPOOL_SHADER_DIR=/nonexistent/shaders"});
}

TEST(BadInput, ShaderThatFailsToCompileNamesFileAndLine) {
  // A copy of the shader folder whose self-test kernel is broken on line 14.
  test::TempDir dir;
  std::filesystem::copy(std::filesystem::path(TIDEPOOL_SOURCE_DIR) / "shaders", dir / "shaders",
                        std::filesystem::copy_options::recursive);
  dir.write("shaders/selftest/fill.comp",
            "#version 430 core\nlayout(local_size_x = 64) in;\n#include \"common/index.glsl\"\n"
            "layout(std430, binding = 0) buffer Out { uint values[]; };\nuniform uint uCount;\nuniform uint uMul;\n"
            "void main() {\n  const uint i = globalIndex();\n  if (i >= uCount) return;\n\n\n\n\n"
            "  values[i] = i * uMul + undefined_name;\n}\n");
  auto r = runTidepool({"info"}, {"TIDEPOOL_SHADER_DIR=" + (dir / "shaders").string()});
  EXPECT_FALSE(r.signaled);
  EXPECT_EQ(r.exitCode, 1);
  const auto lines = r.errLines();
  ASSERT_FALSE(lines.empty());
  EXPECT_NE(lines[0].find("failed to compile at selftest/fill.comp:14"), std::string::npos) << r.err;
}

TEST(BadInput, UnwritableOutputFolder) {
  expectOneLineError({"render", "blank", "--frames", "1", "--out", "/proc/tidepool-out"}, "cannot create output folder",
                     1);
}

TEST(BadInput, FluidParametersNameTheKeyAndTheLimit) {
  test::TempDir dir;
  auto scene = [&](const std::string& name, const std::string& params) {
    dir.write(name, R"({"model": "fluid", "params": )" + params + "}");
    return std::vector<std::string>{"render", (dir / name).string(), "--frames", "1", "--out", (dir / "o").string()};
  };
  expectOneLineError(scene("h.json", R"({"solver": {"smoothing": 0.5}})"),
                     "params.solver.smoothing = 0.5 is out of range [1.01, 4]", 1);
  expectOneLineError(scene("iter.json", R"({"solver": {"iterations": 0}})"),
                     "params.solver.iterations = 0 is out of range [1, 100]", 1);
  expectOneLineError(scene("rho.json", R"({"solver": {"rest_density": 0}})"),
                     "params.solver.rest_density = 0 is out of range [1, 100000]", 1);
  expectOneLineError(scene("many.json", R"({"particles": {"spacing": 0.001, "fill": "block", "fill_min": [0, 0, 0],
                                             "fill_max": [1, 1, 1], "domain_max": [1, 1, 1]}})"),
                     "fluid: particles.spacing = 0.001 m would make about 1e+09 particles, but at most ", 1);
}

TEST(BadInput, FillDenserThanAnyPackingNamesTheCountAndTheKeys) {
  test::TempDir dir;
  // 200,000 particles drawn in a 0.1 mm box: all in one grid cell, a first frame of 4e10 pairs.
  const std::string particles = R"("fill": "random", "random_count": 200000, "fill_min": [0, 0, 0],
                                   "fill_max": [0.0001, 0.0001, 0.0001])";
  dir.write("balls.json", R"({"model": "balls", "params": {"particles": {"radius": 0.01, )" + particles + "}}}");
  expectOneLineError({"render", (dir / "balls.json").string(), "--frames", "1", "--out", (dir / "o").string()},
                     "balls: particles.random_count = 200000 balls do not fit in the random fill's region (8e-06 m^3 "
                     "with particles.radius = 0.01 m): at most 1 do, even hexagonally close packed (74% of the "
                     "space); lower particles.random_count, widen particles.fill_min .. fill_max or lower "
                     "particles.radius",
                     1);
  dir.write("fluid.json", R"({"model": "fluid", "params": {"particles": {"spacing": 0.02, )" + particles + "}}}");
  expectOneLineError({"render", (dir / "fluid.json").string(), "--frames", "1", "--out", (dir / "o").string()},
                     "fluid: particles.random_count = 200000 particles do not fit in the random fill's region "
                     "(8e-06 m^3 with particles.spacing = 0.02 m): at most 1 do",
                     1);
}
