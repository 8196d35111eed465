// A series of exported frames in one folder, in the format asked for:
//   vtk:  frame_00000.vtp, frame_00010.vtp, ... and particles.pvd listing them with their times
//         (ParaView opens the .pvd as one time series);
//   ply:  frame_00000.ply, frame_00010.ply, ... (Blender imports each; the time is a comment);
// and the obstacles once, as a mesh: obstacles.vtp or obstacles.ply. Frame numbers are those of
// the run (frame_00010 is the state the PNG frame_00010.png shows). A heightfield (ripples) is
// written as VTK ImageData, frame_00010.vti, in the same collection; PLY has no form for it.
// A water surface (render/surface_mesher.h) is a triangle mesh per frame: surface_00010.ply (x y z
// nx ny nz, faces), surface_00010.obj (v, vn, f) or surface_00010.vtp listed in surface.pvd.
#pragma once

#include <array>

#include <filesystem>
#include <string>
#include <variant>

#include "io/obj.h"
#include "io/point_cloud.h"
#include "io/vtk_writer.h"

namespace tidepool::io {

enum class ExportFormat { Vtk, Ply, Obj };  // Obj: surfaces only
inline constexpr std::array<const char*, 3> kExportFormatNames = {"vtk", "ply", "obj"};

struct SurfaceFrame {
  double time = 0;    // simulated s
  TriangleMesh mesh;  // with normals
};

using ExportFrame = std::variant<PointCloud, HeightField, SurfaceFrame>;

// --export's particle formats, "vtk" or "ply" (the CLI takes "surface" before asking); anything
// else throws Error "--export 'xyz' is not a format (expected vtk, ply or surface)".
ExportFormat parseExportFormat(const std::string& name);
// --surface-format: "ply", "obj" or "vtk"; anything else throws Error naming them.
ExportFormat parseSurfaceFormat(const std::string& name);
const char* exportExtension(ExportFormat format);  // "vtp", "ply", "obj"

class ExportSeries {
 public:
  // Creates the folder if needed; throws Error naming it when that fails.
  ExportSeries(std::filesystem::path folder, ExportFormat format);
  void write(int frame, const ExportFrame& data);  // throws Error naming the file that failed
  void writeObstacles(const TriangleMesh& mesh);
  int written() const { return m_written; }  // frames
  const std::filesystem::path& folder() const { return m_folder; }
  ExportFormat format() const { return m_format; }
  std::filesystem::path framePath(int frame, bool heightField = false) const;  // folder/frame_00010.vtp (.vti)
  std::filesystem::path surfacePath(int frame) const;                          // folder/surface_00010.ply

 private:
  std::filesystem::path m_folder;
  ExportFormat m_format;
  PvdCollection m_collection, m_surfaces;  // particles.pvd, surface.pvd (vtk)
  int m_written = 0;
};

}  // namespace tidepool::io
