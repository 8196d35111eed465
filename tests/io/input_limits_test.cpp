// Hostile input: every reader refuses what is too large or too deep with one line
// naming the file, the place and the limit, before allocating for it; text quoted from a file
// cannot break that line.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/checkpoint_file.h"  // io::crc32
#include "io/json.h"
#include "io/limits.h"
#include "io/obj.h"
#include "io/png.h"
#include "scene/scene.h"
#include "sim/life/life_rules.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

// The message of the Error that `f` throws ("" when it throws none).
template <class F>
std::string refusal(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// A file of `bytes` bytes that takes no disk space (the readers must refuse it from its size).
std::filesystem::path sparseFile(const test::TempDir& dir, const std::string& name, std::uintmax_t bytes) {
  std::ofstream(dir / name).put('x');
  std::filesystem::resize_file(dir / name, bytes);
  return dir / name;
}

void expectOneLine(const std::string& m) {
  EXPECT_FALSE(m.empty());
  EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  EXPECT_EQ(m.find('\r'), std::string::npos) << m;
}

// A PNG file whose header says width x height, with one IDAT of zeros (too few for the size).
std::vector<std::uint8_t> pngHeader(std::uint32_t width, std::uint32_t height) {
  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  auto chunk = [&](const char* type, std::vector<std::uint8_t> data) {
    for (int i = 3; i >= 0; --i) png.push_back(std::uint8_t(data.size() >> (8 * i)));
    std::vector<std::uint8_t> body(type, type + 4);
    body.insert(body.end(), data.begin(), data.end());
    png.insert(png.end(), body.begin(), body.end());
    const std::uint32_t crc = tidepool::io::crc32(body);
    for (int i = 3; i >= 0; --i) png.push_back(std::uint8_t(crc >> (8 * i)));
  };
  std::vector<std::uint8_t> ihdr;
  for (std::uint32_t v : {width, height})
    for (int i = 3; i >= 0; --i) ihdr.push_back(std::uint8_t(v >> (8 * i)));
  ihdr.insert(ihdr.end(), {8, 6, 0, 0, 0});  // 8-bit RGBA, no interlace
  chunk("IHDR", ihdr);
  chunk("IDAT", {0x78, 0x9c, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01});  // zlib of nothing
  chunk("IEND", {});
  return png;
}

}  // namespace

TEST(InputLimits, JsonFileOverTheSizeLimitIsRefusedBeforeReading) {
  test::TempDir dir;
  const auto big = sparseFile(dir, "big.json", io::kMaxJsonFileBytes + 1);
  const std::string m = refusal([&] { io::readJsonFile(big); });
  expectOneLine(m);
  EXPECT_NE(m.find("big.json' is 16.0 MiB, larger than the 16 MiB allowed for a JSON file"), std::string::npos) << m;
  // The scene and rules loaders go through it.
  EXPECT_NE(refusal([&] { loadScene(big); }).find("16 MiB allowed"), std::string::npos);
  EXPECT_NE(refusal([&] { life::loadRules(big.string()); }).find("16 MiB allowed"), std::string::npos);
}

TEST(InputLimits, DevicesAndPipesAreNotReadForever) {
  const std::string m = refusal([] { io::readJsonFile("/dev/zero"); });
  expectOneLine(m);
  EXPECT_EQ(m, "'/dev/zero' is not a regular file (a device, pipe or socket): give a JSON file");
  EXPECT_NE(refusal([] { io::readObj("/dev/zero"); }).find("give an OBJ mesh"), std::string::npos);
  EXPECT_NE(refusal([] { io::readPng("/dev/zero"); }).find("give a PNG image"), std::string::npos);
}

TEST(InputLimits, JsonNestedTooDeepNamesLineColumnAndLimit) {
  const std::string ok = std::string(io::kMaxJsonDepth, '[') + std::string(io::kMaxJsonDepth, ']');
  EXPECT_NO_THROW(io::parseJson(ok, "ok.json"));
  // Brackets inside strings do not count.
  EXPECT_NO_THROW(io::parseJson("{\"a\": \"" + std::string(1000, '[') + "\\\"[\"}", "s.json"));
  const std::string deep =
      "{\"a\":\n  " + std::string(io::kMaxJsonDepth, '[') + "1" + std::string(io::kMaxJsonDepth, ']') + "}";
  const std::string m = refusal([&] { io::parseJson(deep, "deep.json"); });
  expectOneLine(m);
  EXPECT_EQ(m, "deep.json:2:" + std::to_string(2 + io::kMaxJsonDepth) + ": JSON nested deeper than 64 levels");
}

TEST(InputLimits, ObjFileOverTheSizeLimitIsRefusedBeforeReading) {
  test::TempDir dir;
  const auto big = sparseFile(dir, "big.obj", io::kMaxObjFileBytes + 1);
  const std::string m = refusal([&] { io::readObj(big); });
  expectOneLine(m);
  EXPECT_NE(m.find("big.obj' is 256.0 MiB, larger than the 256 MiB allowed for an OBJ mesh"), std::string::npos) << m;
}

TEST(InputLimits, ObjWithTooManyTrianglesNamesTheLineAndLimit) {
  // One polygon of kMaxObjTriangles + 3 corners fans into one triangle too many.
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3 4\nf 1";
  text.reserve(text.size() + 6 * io::kMaxObjTriangles + 16);
  for (std::size_t i = 0; i < io::kMaxObjTriangles / 3 + 1; ++i) text += " 2 3 4";
  text += "\n";
  const std::string m = refusal([&] { io::parseObj(text, "many.obj"); });
  expectOneLine(m);
  EXPECT_EQ(m, "many.obj:6: more than 4000000 triangles, the most a mesh may have");
}

TEST(InputLimits, ObjQuotesBadTokensOnOneShortLine) {
  // A carriage return alone inside a line separates tokens (a fuzzer found it broke the message).
  const io::TriangleMesh mesh = io::parseObj("v 0 0 0\rv 9\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "cr.obj");
  EXPECT_EQ(mesh.vertices.size(), 3u);
  std::string m = refusal([] {
    io::parseObj(
        "v 0 0 1\x01"
        "2\n",
        "ctl.obj");
  });
  EXPECT_EQ(m, "ctl.obj:1: bad number '1\\x012' in vertex");
  m = refusal([] { io::parseObj("v 0 0 " + std::string(5000, '7') + "x\n", "long.obj"); });
  expectOneLine(m);
  EXPECT_LT(m.size(), 120u) << m;
  EXPECT_NE(m.find("long.obj:1: bad number '777"), std::string::npos) << m;
}

TEST(InputLimits, PngHeaderClaimingTooManyPixelsIsRefusedBeforeDecoding) {
  const std::vector<std::uint8_t> wide = pngHeader(20000, 1);
  std::string m = refusal([&] { io::decodePng(wide, "wide.png"); });
  expectOneLine(m);
  EXPECT_EQ(m, "wide.png: header: 20000 x 1 pixels, larger than the 16384 per side and 64 Mpixel allowed");
  // Each side within the limit, but 256 Mpixel in all (1 GiB as RGBA).
  const std::vector<std::uint8_t> square = pngHeader(16384, 16384);
  m = refusal([&] { io::decodePng(square, "square.png"); });
  EXPECT_EQ(m, "square.png: header: 16384 x 16384 pixels, larger than the 16384 per side and 64 Mpixel allowed");
  // Within the limits, the same too-short data is a decoding error naming the file.
  const std::vector<std::uint8_t> small = pngHeader(4, 4);
  m = refusal([&] { io::decodePng(small, "small.png"); });
  expectOneLine(m);
  EXPECT_EQ(m.rfind("small.png: cannot decode the PNG image (", 0), 0u) << m;
  m = refusal([] { io::decodePng(std::vector<std::uint8_t>{'G', 'I', 'F', '8'}, "x.gif"); });
  EXPECT_EQ(m.rfind("x.gif: not a PNG image (", 0), 0u) << m;
}

TEST(InputLimits, PngFileOverTheSizeLimitIsRefusedBeforeReading) {
  test::TempDir dir;
  const auto big = sparseFile(dir, "big.png", io::kMaxPngFileBytes + 1);
  const std::string m = refusal([&] { io::readPng(big); });
  expectOneLine(m);
  EXPECT_NE(m.find("big.png' is 64.0 MiB, larger than the 64 MiB allowed for a PNG image"), std::string::npos) << m;
}

TEST(InputLimits, ShareCodeLongerThanTheLargestRulesIsRefused) {
  // The largest rules (20 species, a full table) encode to the longest code there is: it loads.
  life::Rules rules = life::generateRules({.species = life::kMaxSpecies, .seed = 3});
  rules.species[0].forces[0].strength += 1.0f;  // no longer what the seed makes: the full table is written
  const std::string longest = life::encodeShareCode(rules);
  EXPECT_TRUE(life::decodeShareCode(longest) == rules);
  const std::string m = refusal([&] { life::decodeShareCode(longest + "AAAA"); });
  expectOneLine(m);
  EXPECT_EQ(m, "share code: " + std::to_string(longest.size() + 4) + " characters, longer than the " +
                   std::to_string(longest.size()) + " of the largest rules (20 species)");
}

TEST(InputLimits, SceneErrorsQuoteKeysAndValuesOnOneShortLine) {
  std::string m = refusal([] { parseScene(io::parseJson(R"({"model": "blank\nx"})", "m.json"), "m.json"); });
  EXPECT_EQ(m.rfind("m.json: scene.model = 'blank\\x0ax' is not a model", 0), 0u) << m;
  m = refusal(
      [] { parseScene(io::parseJson(R"({"model": "blank", "params": {"a\u0007b": 1}})", "k.json"), "k.json"); });
  EXPECT_EQ(m.rfind("k.json: params.a\\x07b: unknown key", 0), 0u) << m;
  std::string array = "[1";
  for (int i = 0; i < 20000; ++i) array += ",1";
  array += "]";
  m = refusal([&] {
    parseScene(io::parseJson(R"({"model": "blank", "params": {"color": )" + array + "}}", "v.json"), "v.json");
  });
  expectOneLine(m);
  EXPECT_LT(m.size(), 200u) << m;
  EXPECT_NE(m.find("v.json: params.color: expected an array of 3 numbers, got [1,1,1"), std::string::npos) << m;
}

TEST(InputLimits, JsonNumbersTooLargeForADoubleNameTheirPlace) {
  const std::string m = refusal([] { io::parseJson("{\"a\": [1,\n 2e999]}", "o.json"); });
  EXPECT_EQ(m, "o.json:2:2: malformed JSON: number overflow parsing '2e999'");
}

TEST(InputLimits, PngChunksAndImageDataAreCheckedBeforeStbTrustsThem) {
  // A chunk length larger than the file: stb would allocate what it claims (a fuzzer found this).
  std::vector<std::uint8_t> png = pngHeader(4, 4);
  png[33] = 0x31;  // the IDAT chunk's length, big-endian at byte 33: now 0x31000008
  std::string m = refusal([&] { io::decodePng(png, "long.png"); });
  expectOneLine(m);
  EXPECT_EQ(m.rfind("long.png: byte 33: chunk 'IDAT' claims 822083592 bytes and its checksum, but only ", 0), 0u) << m;

  test::TempDir dir;
  auto written = [&](int width, int height) {
    io::writePng(dir / "w.png", io::Image{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4)});
    std::ifstream in(dir / "w.png", std::ios::binary);
    return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {});
  };
  auto claim = [](std::vector<std::uint8_t> bytes, std::uint32_t width, std::uint32_t height) {
    for (int i = 0; i < 4; ++i) {
      bytes[16 + std::size_t(i)] = std::uint8_t(width >> (24 - 8 * i));
      bytes[20 + std::size_t(i)] = std::uint8_t(height >> (24 - 8 * i));
    }
    return bytes;
  };
  // A decompression bomb: 4 MiB of pixels squeezed into a few KiB behind a 16 x 16 header.
  m = refusal([&] { io::decodePng(claim(written(1024, 1024), 16, 16), "bomb.png"); });
  expectOneLine(m);
  EXPECT_EQ(m,
            "bomb.png: its image data inflates to more than the 1040 bytes its 16 x 16 pixels need "
            "(a decompression bomb?)");
  // The other way round: far too little data for the pixels claimed, refused before stb allocates them.
  m = refusal([&] { io::decodePng(claim(written(2, 2), 8192, 8192), "thin.png"); });
  expectOneLine(m);
  EXPECT_NE(m.find("thin.png: "), std::string::npos) << m;
  EXPECT_NE(m.find(" bytes of image data cannot fill the 8192 x 8192 pixels its header claims"), std::string::npos)
      << m;
  // An empty IDAT before the data: stb would copy its zero bytes to a null pointer (a fuzzer
  // found this undefined behaviour; tests/fuzz/regressions/png/empty-first-idat.png).
  std::vector<std::uint8_t> empty = written(2, 2);
  const std::vector<std::uint8_t> type = {'I', 'D', 'A', 'T'};
  const std::uint32_t crc = io::crc32(type);
  std::vector<std::uint8_t> chunk = {0, 0, 0, 0, 'I', 'D', 'A', 'T'};
  for (int i = 3; i >= 0; --i) chunk.push_back(std::uint8_t(crc >> (8 * i)));
  empty.insert(empty.begin() + 33, chunk.begin(), chunk.end());  // right after IHDR
  m = refusal([&] { io::decodePng(empty, "empty.png"); });
  expectOneLine(m);
  EXPECT_EQ(m, "empty.png: byte 33: chunk 'IDAT' is empty, which the decoder cannot read (re-save the image)");
  // A deflate block of the reserved type 3: stb fails without a reason (reading it crashed).
  std::vector<std::uint8_t> reserved = pngHeader(2, 2);
  const std::vector<std::uint8_t> idat = {'I', 'D', 'A', 'T', 0x78, 0x9c, 0x07, 0, 0, 0, 0, 1};
  std::copy(idat.begin(), idat.end(), reserved.begin() + 37);  // same length: only the CRC is off
  m = refusal([&] { io::decodePng(reserved, "reserved.png"); });
  expectOneLine(m);
  EXPECT_EQ(m, "reserved.png: cannot decode the PNG image (damaged image data; the decoder gives no reason)");
  // Untouched, both decode.
  EXPECT_EQ(io::decodePng(written(1024, 1024), "w.png").width, 1024);
  EXPECT_EQ(io::decodePng(written(2, 2), "w.png").rgba.size(), 16u);
}
