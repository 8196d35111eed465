#include "io/vtk_writer.h"

#include <bit>
#include <cstdio>
#include <cstring>

#include "base/error.h"
#include "io/output_file.h"

namespace tidepool::io {
namespace {

static_assert(std::endian::native == std::endian::little, "the files are written as the host's bytes");

const char* typeName(PointType t) {
  switch (t) {
    case PointType::Int32: return "Int32";
    case PointType::UInt8: return "UInt8";
    default: return "Float32";
  }
}

// The XML lines of the arrays and the appended block they point into.
class Appended {
 public:
  explicit Appended(std::size_t expectedBytes) { m_block.reserve(expectedBytes); }
  // <DataArray ... offset="..."/> for `bytes` of `type`, appended after the arrays added so far.
  std::string array(const std::string& name, const char* type, std::size_t components, const void* data,
                    std::size_t bytes) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "        <DataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%zu\" format=\"appended\" "
                  "offset=\"%zu\"/>\n",
                  type, name.c_str(), components, m_block.size());
    const std::uint64_t size = bytes;
    append(&size, sizeof size);
    append(data, bytes);
    return line;
  }
  std::string field(const PointField& f) {
    std::vector<std::uint8_t> raw(f.values.size() * pointTypeBytes(f.type));
    for (std::size_t i = 0; i < f.values.size(); ++i) {
      if (f.type == PointType::Float32) std::memcpy(&raw[4 * i], &f.values[i], 4);
      if (f.type == PointType::UInt8) raw[i] = std::uint8_t(f.values[i]);
      if (f.type == PointType::Int32) {
        const std::int32_t v = std::int32_t(f.values[i]);
        std::memcpy(&raw[4 * i], &v, 4);
      }
    }
    return array(f.name, typeName(f.type), f.components(), raw.data(), raw.size());
  }
  const std::vector<std::uint8_t>& block() const { return m_block; }

 private:
  void append(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    m_block.insert(m_block.end(), p, p + bytes);
  }
  std::vector<std::uint8_t> m_block;
};

// One cell per run of `per` points: connectivity 0 1 2 ..., offsets per, 2 per, ... (cell ends).
std::string cells(Appended& a, const char* tag, std::size_t points, std::size_t per) {
  std::vector<std::int32_t> connectivity(points), offsets(points / per);
  for (std::size_t i = 0; i < points; ++i) connectivity[i] = std::int32_t(i);
  for (std::size_t i = 0; i < offsets.size(); ++i) offsets[i] = std::int32_t((i + 1) * per);
  std::string xml = std::string("      <") + tag + ">\n";
  xml += a.array("connectivity", "Int32", 1, connectivity.data(), connectivity.size() * 4);
  xml += a.array("offsets", "Int32", 1, offsets.data(), offsets.size() * 4);
  return xml + "      </" + tag + ">\n";
}

// The whole file: `type`'s element (with `attributes`), one piece, the arrays, the appended block.
std::vector<std::uint8_t> file(const char* type, const std::string& attributes, const std::string& piece,
                               const std::string& arrays, const Appended& a) {
  const std::string head = std::string("<?xml version=\"1.0\"?>\n") + "<VTKFile type=\"" + type +
                           "\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <" + type +
                           attributes + ">\n    <Piece" + piece + ">\n" + arrays + "    </Piece>\n  </" + type +
                           ">\n  <AppendedData encoding=\"raw\">\n   _";
  const std::string tail = "\n  </AppendedData>\n</VTKFile>\n";
  std::vector<std::uint8_t> out;
  out.reserve(head.size() + a.block().size() + tail.size());
  out.insert(out.end(), head.begin(), head.end());
  out.insert(out.end(), a.block().begin(), a.block().end());
  out.insert(out.end(), tail.begin(), tail.end());
  return out;
}

std::string polyPiece(std::size_t points, std::size_t verts, std::size_t polys) {
  char piece[256];
  std::snprintf(piece, sizeof piece,
                " NumberOfPoints=\"%zu\" NumberOfVerts=\"%zu\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
                "NumberOfPolys=\"%zu\"",
                points, verts, polys);
  return piece;
}

void checkIndexable(std::size_t n, const char* what) {
  if (n >= (std::size_t(1) << 31))
    throw Error(std::string("VTK export: ") + std::to_string(n) + " " + what + " is more than Int32 cells can index");
}

}  // namespace

std::vector<std::uint8_t> vtpBytes(const PointCloud& cloud) {
  checkPointCloud(cloud);
  const std::size_t n = cloud.size();
  checkIndexable(n, "points");
  std::size_t expected = 8 * 8 + n * (12 + 8);  // headers, points, connectivity and offsets
  for (const PointField& f : cloud.fields) expected += f.values.size() * pointTypeBytes(f.type);
  Appended a(expected);
  std::string arrays = "      <PointData>\n";
  for (const PointField& f : cloud.fields) arrays += a.field(f);
  arrays += "      </PointData>\n      <Points>\n";
  arrays += a.array("Points", "Float32", 3, cloud.positions.data(), cloud.positions.size() * 4);
  arrays += "      </Points>\n";
  arrays += cells(a, "Verts", n, 1);
  return file("PolyData", "", polyPiece(n, n, 0), arrays, a);
}

std::vector<std::uint8_t> vtpBytes(const TriangleMesh& mesh) {
  checkIndexable(mesh.triangles.size() * 3, "triangle corners");
  Appended a(4 * 8 + mesh.vertices.size() * 12 + mesh.triangles.size() * 16);
  std::string arrays = "      <Points>\n";
  arrays += a.array("Points", "Float32", 3, mesh.vertices.data(), mesh.vertices.size() * sizeof(glm::vec3));
  arrays += "      </Points>\n      <Polys>\n";
  std::vector<std::int32_t> connectivity, offsets;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) connectivity.push_back(std::int32_t(mesh.triangles[t][k]));
    offsets.push_back(std::int32_t(3 * (t + 1)));
  }
  arrays += a.array("connectivity", "Int32", 1, connectivity.data(), connectivity.size() * 4);
  arrays += a.array("offsets", "Int32", 1, offsets.data(), offsets.size() * 4);
  arrays += "      </Polys>\n";
  return file("PolyData", "", polyPiece(mesh.vertices.size(), 0, mesh.triangles.size()), arrays, a);
}

std::vector<std::uint8_t> vtiBytes(const HeightField& grid) {
  checkHeightField(grid);
  std::size_t expected = 8 * grid.fields.size();
  for (const PointField& f : grid.fields) expected += f.values.size() * pointTypeBytes(f.type);
  Appended a(expected);
  std::string arrays = "      <PointData>\n";
  for (const PointField& f : grid.fields) arrays += a.field(f);
  arrays += "      </PointData>\n";
  char extent[64], attributes[256];
  std::snprintf(extent, sizeof extent, "0 %d 0 %d 0 0", grid.width - 1, grid.height - 1);
  std::snprintf(attributes, sizeof attributes, " WholeExtent=\"%s\" Origin=\"%.9g %.9g 0\" Spacing=\"%.9g %.9g %.9g\"",
                extent, double(grid.origin[0]), double(grid.origin[1]), double(grid.spacing), double(grid.spacing),
                double(grid.spacing));
  return file("ImageData", attributes, std::string(" Extent=\"") + extent + "\"", arrays, a);
}

void writeVti(const std::filesystem::path& path, const HeightField& grid) { replaceFile(path, vtiBytes(grid)); }

void writeVtp(const std::filesystem::path& path, const PointCloud& cloud) { replaceFile(path, vtpBytes(cloud)); }

void writeVtp(const std::filesystem::path& path, const TriangleMesh& mesh) { replaceFile(path, vtpBytes(mesh)); }

std::string PvdCollection::text() const {
  std::string out =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const auto& [time, dataFile] : m_entries) {
    char line[512];
    std::snprintf(line, sizeof line, "    <DataSet timestep=\"%.9g\" group=\"\" part=\"0\" file=\"%s\"/>\n", time,
                  dataFile.c_str());
    out += line;
  }
  return out + "  </Collection>\n</VTKFile>\n";
}

void PvdCollection::add(double time, const std::string& dataFile) {
  m_entries.emplace_back(time, dataFile);
  const std::string t = text();
  replaceFile(m_file, {reinterpret_cast<const std::uint8_t*>(t.data()), t.size()});
}

}  // namespace tidepool::io
