#include "io/ply_writer.h"

#include <bit>
#include <cstdio>
#include <cstring>
#include <string>

#include "base/error.h"
#include "io/output_file.h"

namespace tidepool::io {
namespace {

static_assert(std::endian::native == std::endian::little, "the files are written as the host's bytes");

const char* plyType(PointType t) {
  switch (t) {
    case PointType::Int32: return "int";
    case PointType::UInt8: return "uchar";
    default: return "float";
  }
}

std::vector<std::uint8_t> headerBytes(const std::string& header) {
  return std::vector<std::uint8_t>(header.begin(), header.end());
}

template <class T>
void put(std::vector<std::uint8_t>& out, T value) {
  std::uint8_t raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  out.insert(out.end(), raw, raw + sizeof(T));
}

}  // namespace

std::vector<std::uint8_t> plyBytes(const PointCloud& cloud) {
  checkPointCloud(cloud);
  char comment[96];
  std::snprintf(comment, sizeof comment, "comment tidepool time %.9g\n", cloud.time);
  std::string header = std::string("ply\nformat binary_little_endian 1.0\n") + comment + "element vertex " +
                       std::to_string(cloud.size()) + "\nproperty float x\nproperty float y\nproperty float z\n";
  std::size_t stride = 12;
  for (const PointField& f : cloud.fields)
    for (const std::string& part : f.parts) {
      header += std::string("property ") + plyType(f.type) + " " + part + "\n";
      stride += pointTypeBytes(f.type);
    }
  header += "end_header\n";
  const std::size_t body = header.size();
  std::vector<std::uint8_t> out(body + stride * cloud.size());
  std::memcpy(out.data(), header.data(), body);
  // Column by column into the packed rows: each field is one pass over the points.
  std::size_t column = 0;
  const auto fill = [&](const float* values, std::size_t components, PointType type) {
    for (std::size_t c = 0; c < components; ++c) {
      std::uint8_t* row = out.data() + body + column;
      for (std::size_t i = 0; i < cloud.size(); ++i, row += stride) {
        const float v = values[i * components + c];
        if (type == PointType::Float32) std::memcpy(row, &v, 4);
        if (type == PointType::Int32) {
          const std::int32_t n = std::int32_t(v);
          std::memcpy(row, &n, 4);
        }
        if (type == PointType::UInt8) *row = std::uint8_t(v);
      }
      column += pointTypeBytes(type);
    }
  };
  fill(cloud.positions.data(), 3, PointType::Float32);
  for (const PointField& f : cloud.fields) fill(f.values.data(), f.components(), f.type);
  return out;
}

std::vector<std::uint8_t> plyBytes(const TriangleMesh& mesh, std::optional<double> time, bool withNormals) {
  const bool normals = withNormals || !mesh.normals.empty();
  if (normals && mesh.normals.size() != mesh.vertices.size())
    throw Error("a mesh has " + std::to_string(mesh.normals.size()) + " normals for " +
                std::to_string(mesh.vertices.size()) + " vertices");
  std::string header = "ply\nformat binary_little_endian 1.0\n";
  if (time) {
    char comment[96];
    std::snprintf(comment, sizeof comment, "comment tidepool time %.9g\n", *time);
    header += comment;
  }
  header += "element vertex " + std::to_string(mesh.vertices.size()) +
            "\nproperty float x\nproperty float y\nproperty float z\n" +
            (normals ? "property float nx\nproperty float ny\nproperty float nz\n" : "") + "element face " +
            std::to_string(mesh.triangles.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  std::vector<std::uint8_t> out = headerBytes(header);
  out.reserve(out.size() + mesh.vertices.size() * (normals ? 24 : 12) + mesh.triangles.size() * 13);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    for (int k = 0; k < 3; ++k) put(out, mesh.vertices[i][k]);
    if (normals)
      for (int k = 0; k < 3; ++k) put(out, mesh.normals[i][k]);
  }
  for (const glm::uvec3& t : mesh.triangles) {
    put(out, std::uint8_t(3));
    for (int k = 0; k < 3; ++k) put(out, std::int32_t(t[k]));
  }
  return out;
}

void writePly(const std::filesystem::path& file, const PointCloud& cloud) { replaceFile(file, plyBytes(cloud)); }

void writePly(const std::filesystem::path& file, const TriangleMesh& mesh, std::optional<double> time, bool normals) {
  replaceFile(file, plyBytes(mesh, time, normals));
}

}  // namespace tidepool::io
