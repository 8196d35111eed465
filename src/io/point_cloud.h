// Particles as plain CPU arrays, ready for a file: positions and named per-point fields, at one
// simulated time (and a heightfield: fields on a regular grid of points). The exporters
// (vtk_writer.h, ply_writer.h) write them; nothing here knows GL.
//
//   PointCloud c{0.5, {x0, y0, z0, x1, y1, z1}, {}};
//   c.fields.push_back({"velocity", {"vx", "vy", "vz"}, PointType::Float32, {vx0, vy0, vz0, vx1, vy1, vz1}});
//   c.fields.push_back({"species", {"species"}, PointType::Int32, {2, 0}});
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace tidepool::io {

enum class PointType { Float32, Int32, UInt8 };
inline std::size_t pointTypeBytes(PointType t) { return t == PointType::UInt8 ? 1 : 4; }  // as written

struct PointField {
  std::string name;                // "velocity", "foam", "species", "density", "color" (VTK's array name)
  std::vector<std::string> parts;  // one name per component, PLY's properties: {"vx", "vy", "vz"}, {"foam"}
  PointType type = PointType::Float32;
  std::vector<float> values;  // size() * parts.size(), point by point; integral for Int32 / UInt8
  std::size_t components() const { return parts.size(); }
};

struct PointCloud {
  double time = 0;               // simulated s
  std::vector<float> positions;  // x y z per point
  std::vector<PointField> fields;
  std::size_t size() const { return positions.size() / 3; }
};

// Fields on width x height points of a regular grid in the z = 0 plane: point (i, j) at
// origin + spacing·(i, j), listed row by row (i fastest), as the ripples model stores its cells.
struct HeightField {
  double time = 0;  // simulated s
  int width = 0, height = 0;
  float spacing = 1;  // m between neighbouring points
  float origin[2] = {0, 0};
  std::vector<PointField> fields;  // "height", "vertical_velocity": width·height values each
  std::size_t size() const { return std::size_t(width) * std::size_t(height); }
};

// Throws Error when a field's values do not match the points (a bug in whoever filled it).
void checkPointCloud(const PointCloud& cloud);
void checkHeightField(const HeightField& field);

}  // namespace tidepool::io
