// Binary little-endian PLY, which Blender (File > Import > Stanford PLY) and ParaView open:
//
//   ply
//   format binary_little_endian 1.0
//   comment tidepool time 0.5            (simulated s)
//   element vertex 2
//   property float x                     (y, z; then each field's parts: vx vy vz, foam ...)
//   property int species                 (PointType::Int32; UInt8 is uchar: red green blue)
//   end_header
//   [x y z vx vy vz ... species] per vertex, packed, no padding
//
// A triangle mesh adds "element face N" with "property list uchar int vertex_indices"; with
// normals its vertices are x y z nx ny nz (Blender reads them as custom split normals), and with a
// time the header carries the same comment as a point cloud's.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "io/obj.h"
#include "io/point_cloud.h"

namespace tidepool::io {

std::vector<std::uint8_t> plyBytes(const PointCloud& cloud);  // throws Error (checkPointCloud)
// `normals`: nx ny nz even for an empty mesh (a frame of a series whose other frames have them).
std::vector<std::uint8_t> plyBytes(const TriangleMesh& mesh, std::optional<double> time = std::nullopt,
                                   bool normals = false);
void writePly(const std::filesystem::path& file, const PointCloud& cloud);  // replaceFile (io/output_file.h)
void writePly(const std::filesystem::path& file, const TriangleMesh& mesh, std::optional<double> time = std::nullopt,
              bool normals = false);

}  // namespace tidepool::io
