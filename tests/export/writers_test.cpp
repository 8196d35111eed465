// The export writers on CPU arrays: the exact bytes of PLY (header and packed body), the VTP's
// XML against its appended block (every array's offset points at a UInt64 size and then exactly
// the values given), the .pvd collection, and writes that fail with one line naming the file.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <regex>
#include <string>

#include "base/error.h"
#include "io/export_series.h"
#include "io/output_file.h"
#include "io/ply_writer.h"
#include "io/vtk_writer.h"
#include "support/gl_test.h"

using namespace tidepool;
using tidepool::io::PointType;

namespace {

// Two points: velocity (3 floats), foam (float), species (int), colour (3 bytes).
io::PointCloud twoPoints() {
  io::PointCloud c;
  c.time = 0.25;
  c.positions = {1.0f, 2.0f, 3.0f, -1.5f, 0.5f, 0.0f};
  c.fields.push_back({"velocity", {"vx", "vy", "vz"}, PointType::Float32, {0.1f, 0.2f, 0.3f, 4.0f, 5.0f, 6.0f}});
  c.fields.push_back({"foam", {"foam"}, PointType::Float32, {0.75f, 0.0f}});
  c.fields.push_back({"species", {"species"}, PointType::Int32, {3.0f, 1.0f}});
  c.fields.push_back({"color", {"red", "green", "blue"}, PointType::UInt8, {255.0f, 128.0f, 0.0f, 1.0f, 2.0f, 3.0f}});
  return c;
}

template <class T>
void append(std::string& s, T v) {
  char raw[sizeof(T)];
  std::memcpy(raw, &v, sizeof(T));
  s.append(raw, sizeof(T));
}

std::string text(const std::vector<std::uint8_t>& bytes) { return std::string(bytes.begin(), bytes.end()); }

std::string readFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

template <class T>
T valueAt(const std::string& s, std::size_t at) {
  T v;
  std::memcpy(&v, s.data() + at, sizeof(T));
  return v;
}

}  // namespace

TEST(ExportWriters, PlyHeaderAndPackedRowsAreExact) {
  std::string expected =
      "ply\nformat binary_little_endian 1.0\ncomment tidepool time 0.25\nelement vertex 2\n"
      "property float x\nproperty float y\nproperty float z\n"
      "property float vx\nproperty float vy\nproperty float vz\nproperty float foam\nproperty int species\n"
      "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  for (float v : {1.0f, 2.0f, 3.0f, 0.1f, 0.2f, 0.3f, 0.75f}) append(expected, v);
  append(expected, std::int32_t(3));
  for (std::uint8_t v : {255, 128, 0}) append(expected, v);
  for (float v : {-1.5f, 0.5f, 0.0f, 4.0f, 5.0f, 6.0f, 0.0f}) append(expected, v);
  append(expected, std::int32_t(1));
  for (std::uint8_t v : {1, 2, 3}) append(expected, v);
  EXPECT_EQ(text(io::plyBytes(twoPoints())), expected);
}

TEST(ExportWriters, PlyMeshHasFacesAsUcharCountAndIntIndices) {
  io::TriangleMesh mesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}};
  std::string expected =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  for (float v : {0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f}) append(expected, v);
  append(expected, std::uint8_t(3));
  for (std::int32_t i : {0, 1, 2}) append(expected, i);
  EXPECT_EQ(text(io::plyBytes(mesh)), expected);
}

TEST(ExportWriters, VtpArraysPointAtTheirSizedBlocksInTheAppendedData) {
  const std::string vtp = text(io::vtpBytes(twoPoints()));
  EXPECT_NE(vtp.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(vtp.find("NumberOfPoints=\"2\" NumberOfVerts=\"2\""), std::string::npos) << vtp.substr(0, 600);
  const std::size_t marker = vtp.find("<AppendedData encoding=\"raw\">\n   _");
  ASSERT_NE(marker, std::string::npos);
  const std::size_t base = vtp.find('_', marker) + 1;
  // Each array: its type, components and the values it must hold, at its offset.
  struct Expected {
    const char* name;
    const char* type;
    int components;
    std::string bytes;
  };
  std::vector<Expected> arrays = {{"velocity", "Float32", 3, ""}, {"foam", "Float32", 1, ""},
                                  {"species", "Int32", 1, ""},    {"color", "UInt8", 3, ""},
                                  {"Points", "Float32", 3, ""},   {"connectivity", "Int32", 1, ""},
                                  {"offsets", "Int32", 1, ""}};
  for (float v : {0.1f, 0.2f, 0.3f, 4.0f, 5.0f, 6.0f}) append(arrays[0].bytes, v);
  for (float v : {0.75f, 0.0f}) append(arrays[1].bytes, v);
  for (std::int32_t v : {3, 1}) append(arrays[2].bytes, v);
  for (std::uint8_t v : {255, 128, 0, 1, 2, 3}) append(arrays[3].bytes, v);
  for (float v : {1.0f, 2.0f, 3.0f, -1.5f, 0.5f, 0.0f}) append(arrays[4].bytes, v);
  for (std::int32_t v : {0, 1}) append(arrays[5].bytes, v);
  for (std::int32_t v : {1, 2}) append(arrays[6].bytes, v);
  std::size_t end = 0;
  for (const Expected& e : arrays) {
    const std::regex line(std::string("<DataArray type=\"") + e.type + "\" Name=\"" + e.name +
                          "\" NumberOfComponents=\"" + std::to_string(e.components) +
                          "\" format=\"appended\" offset=\"([0-9]+)\"/>");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(vtp, m, line)) << e.name;
    const std::size_t at = base + std::stoul(m[1]);
    EXPECT_EQ(valueAt<std::uint64_t>(vtp, at), e.bytes.size()) << e.name;
    EXPECT_EQ(vtp.substr(at + 8, e.bytes.size()), e.bytes) << e.name;
    end = std::max(end, at + 8 + e.bytes.size());
  }
  EXPECT_EQ(vtp.substr(end), "\n  </AppendedData>\n</VTKFile>\n");  // nothing unaccounted for
}

TEST(ExportWriters, VtpMeshHasTrianglePolys) {
  io::TriangleMesh mesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 1, 2}, {0, 2, 3}}};
  const std::string vtp = text(io::vtpBytes(mesh));
  EXPECT_NE(vtp.find("NumberOfPoints=\"4\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
                     "NumberOfPolys=\"2\""),
            std::string::npos);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(vtp, m,
                                std::regex("Name=\"offsets\" NumberOfComponents=\"1\" "
                                           "format=\"appended\" offset=\"([0-9]+)\"")));
  const std::size_t at = vtp.find('_', vtp.find("<AppendedData")) + 1 + std::stoul(m[1]);
  EXPECT_EQ(valueAt<std::uint64_t>(vtp, at), 8u);
  EXPECT_EQ(valueAt<std::int32_t>(vtp, at + 8), 3);
  EXPECT_EQ(valueAt<std::int32_t>(vtp, at + 12), 6);
}

TEST(ExportWriters, VtiIsImageDataWithTheGridAndItsFieldsRowByRow) {
  io::HeightField grid{1.5, 3, 2, 0.25f, {0.125f, 0.125f}, {}};
  grid.fields.push_back({"height", {"height"}, PointType::Float32, {0, 1, 2, 3, 4, 5}});
  const std::string vti = text(io::vtiBytes(grid));
  EXPECT_NE(vti.find("<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" "
                     "header_type=\"UInt64\">"),
            std::string::npos)
      << vti.substr(0, 400);
  EXPECT_NE(vti.find("<ImageData WholeExtent=\"0 2 0 1 0 0\" Origin=\"0.125 0.125 0\" Spacing=\"0.25 0.25 0.25\">"),
            std::string::npos)
      << vti.substr(0, 400);
  EXPECT_NE(vti.find("<Piece Extent=\"0 2 0 1 0 0\">"), std::string::npos) << vti.substr(0, 400);
  EXPECT_NE(vti.find("Name=\"height\" NumberOfComponents=\"1\" format=\"appended\" offset=\"0\""), std::string::npos);
  const std::size_t base = vti.find('_', vti.find("<AppendedData")) + 1;
  EXPECT_EQ(valueAt<std::uint64_t>(vti, base), 24u);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(valueAt<float>(vti, base + 8 + 4 * i), float(i));
  EXPECT_EQ(vti.substr(base + 8 + 24), "\n  </AppendedData>\n</VTKFile>\n");
  // PLY has no form for it.
  test::TempDir dir;
  io::ExportSeries ply(dir / "ply", io::ExportFormat::Ply);
  EXPECT_THROW(ply.write(0, grid), Error);
}

TEST(ExportWriters, MismatchedFieldIsRefusedByName) {
  io::PointCloud c = twoPoints();
  c.fields[1].values.pop_back();
  try {
    io::plyBytes(c);
    FAIL() << "a foam field one value short was written";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("field 'foam' has 1 values for 2 points"), std::string::npos) << e.what();
  }
}

TEST(ExportWriters, SeriesWritesFramesAndACollectionListingThemWithTimes) {
  test::TempDir dir;
  io::ExportSeries series(dir / "out", io::ExportFormat::Vtk);
  io::PointCloud c = twoPoints();
  series.write(0, c);
  c.time = 0.5;
  series.write(10, c);
  EXPECT_EQ(series.written(), 2);
  EXPECT_TRUE(std::filesystem::exists(dir / "out/frame_00000.vtp"));
  EXPECT_TRUE(std::filesystem::exists(dir / "out/frame_00010.vtp"));
  const std::string pvd = readFile(dir / "out/particles.pvd");
  EXPECT_NE(pvd.find("<DataSet timestep=\"0.25\" group=\"\" part=\"0\" file=\"frame_00000.vtp\"/>"), std::string::npos)
      << pvd;
  EXPECT_NE(pvd.find("<DataSet timestep=\"0.5\" group=\"\" part=\"0\" file=\"frame_00010.vtp\"/>"), std::string::npos)
      << pvd;
  EXPECT_FALSE(std::filesystem::exists(dir / "out/particles.pvd.tmp"));
  EXPECT_EQ(io::parseExportFormat("ply"), io::ExportFormat::Ply);
  EXPECT_THROW(io::parseExportFormat("xyz"), Error);
}

TEST(ExportWriters, AFolderThatIsAFileIsOneLineNamingIt) {
  test::TempDir dir;
  dir.write("file", "x");
  try {
    io::ExportSeries series(dir / "file/out", io::ExportFormat::Ply);
    FAIL() << "made a folder under a regular file";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot create export folder '" + (dir / "file/out").string() + "'"),
              std::string::npos)
        << e.what();
  }
  try {
    const std::uint8_t byte = 1;
    io::replaceFile(dir / "file/frame.ply", {&byte, 1});
    FAIL() << "wrote under a regular file";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write '" + (dir / "file/frame.ply").string() + "': Not a directory"),
              std::string::npos)
        << e.what();
  }
}
