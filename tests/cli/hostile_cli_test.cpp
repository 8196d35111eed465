// Hostile input through the program: files too large, too deep or not files at all
// end the run with one line naming the file, the place and the limit, and exit status 1.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <fstream>

#include "support/gl_test.h"
#include "support/one_line_error.h"

using namespace tidepool;
using test::expectOneLineError;

namespace {

std::string sparse(const test::TempDir& dir, const std::string& name, std::uintmax_t bytes) {
  std::ofstream(dir / name).put('{');
  std::filesystem::resize_file(dir / name, bytes);
  return (dir / name).string();
}

}  // namespace

TEST(HostileCli, SceneFileTooLargeOrTooDeep) {
  test::TempDir dir;
  const std::string big = sparse(dir, "big.json", 40u << 20);
  expectOneLineError({"render", big, "--out", (dir / "o").string()},
                     big + "' is 40 MiB, larger than the 16 MiB allowed for a JSON file");
  dir.write("deep.json", "{\"model\": \"blank\", \"params\":\n" + std::string(100000, '[') + "}");
  expectOneLineError({"render", (dir / "deep.json").string(), "--out", (dir / "o").string()},
                     (dir / "deep.json").string() + ":2:64: JSON nested deeper than 64 levels");
  expectOneLineError({"render", "/dev/zero", "--out", (dir / "o").string()},
                     "'/dev/zero' is not a regular file (a device, pipe or socket): give a JSON file");
}

TEST(HostileCli, RulesTooLongOrNotAFile) {
  test::TempDir dir;
  expectOneLineError(
      {"render", "life", "--rules", std::string(20000, 'A'), "--out", (dir / "o").string()},
      "params.rules: share code: 20000 characters, longer than the 9002 of the largest rules (20 species)");
  expectOneLineError({"render", "life", "--rules", "/dev/zero", "--out", (dir / "o").string()},
                     "params.rules: '/dev/zero' is not a regular file");
}

TEST(HostileCli, ObstacleMeshTooLarge) {
  test::TempDir dir;
  const std::string mesh = sparse(dir, "huge.obj", 300u << 20);
  dir.write("s.json", R"({"model": "balls", "params": {"particles": {"fill": "none"},
                          "obstacles": [{"shape": "mesh", "mesh": ")" +
                          mesh + R"("}]}})");
  test::expectRenderFails((dir / "s.json").string(), (dir / "o").string(),
                          "huge.obj' is 300 MiB, larger than the 256 MiB allowed for an OBJ mesh");
}

TEST(HostileCli, SwarmImageMissingTooLargeTruncatedOrNotAFile) {
  test::TempDir dir;
  auto scene = [&](const std::string& name, const std::string& image) {
    dir.write(name, R"({"model": "swarm", "params": {"particles": 1000,
                        "view": {"color_mode": "image", "image": ")" +
                        image + R"("}}})");
    return std::vector<std::string>{"render", (dir / name).string(), "--frames", "2", "--size", "32x16",
                                    "--out",  (dir / "o").string()};
  };
  const std::string key = ": params.view.image = '";
  expectOneLineError(scene("missing.json", "nosuchimage"),
                     (dir / "missing.json").string() + key + "nosuchimage': file not found: 'nosuchimage'");
  const std::string big = sparse(dir, "big.png", 80u << 20);
  expectOneLineError(scene("big.json", big), key + big + "': '" + big + "' is 80 MiB, larger than the 64 MiB allowed");
  // The first 60 bytes of a real PNG: the header, then a cut image data chunk.
  const std::string whole = (std::filesystem::path(TIDEPOOL_SOURCE_DIR) / "assets/textures/colors.png").string();
  std::string bytes(60, '\0');
  std::ifstream(whole, std::ios::binary).read(bytes.data(), 60);
  dir.write("cut.png", bytes);
  expectOneLineError(scene("cut.json", (dir / "cut.png").string()),
                     key + (dir / "cut.png").string() + "': " + (dir / "cut.png").string() + ": byte 33: chunk 'IDAT'");
  expectOneLineError(
      scene("zero.json", "/dev/zero"),
      key + "/dev/zero': '/dev/zero' is not a regular file (a device, pipe or socket): give a PNG image");
  ASSERT_EQ(mkfifo((dir / "fifo").c_str(), 0600), 0);
  expectOneLineError(scene("fifo.json", (dir / "fifo").string()), "fifo' is not a regular file");
  // A name with a line break in it stays on the line, escaped.
  expectOneLineError(scene("nl.json", "a\\nb"), key + "a\\x0ab': file not found: 'a\\x0ab'");
}

TEST(HostileCli, SetTooLongOrTooDeep) {
  test::TempDir dir;
  const std::string out = (dir / "o").string();
  // 100,000 characters of key: once a stack overflow in std::regex_match.
  const test::ProcessResult r = expectOneLineError(
      {"render", "blank", "--set", std::string(100000, 'a') + "=1", "--out", out}, "params.aaaaaaaaaa");
  EXPECT_LT(r.err.size(), 400u) << "the key is cut";
  // 10,000 levels of key: once 35 s of building, now refused at the depth of a scene file.
  std::string deep = "a";
  for (int i = 0; i < 10000; ++i) deep += ".a";
  expectOneLineError({"render", "blank", "--set", deep + "=1", "--out", out},
                     "the key is nested deeper than the 64 levels a scene may nest");
  expectOneLineError({"render", "blank", "--set", "a.b.c=" + std::string(62, '[') + std::string(62, ']'), "--out", out},
                     "the key and the value together are nested deeper than the 64 levels a scene may nest");
  for (const char* bad : {"=1", "a=", "a..b=1", "a.=1", ".a=1", "1a=1", "a-b=1", "a"})
    expectOneLineError({"render", "blank", "--set", bad, "--out", out}, "is not KEY=VALUE with a params key");
}
