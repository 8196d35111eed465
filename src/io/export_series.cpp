#include "io/export_series.h"

#include <cstdio>

#include "base/error.h"
#include "io/echo.h"
#include "io/ply_writer.h"

namespace tidepool::io {

ExportFormat parseExportFormat(const std::string& name) {
  if (name == "vtk") return ExportFormat::Vtk;
  if (name == "ply") return ExportFormat::Ply;
  throw Error("--export '" + printable(name) + "' is not a format (expected vtk, ply or surface)");
}

ExportFormat parseSurfaceFormat(const std::string& name) {
  for (std::size_t k = 0; k < kExportFormatNames.size(); ++k)
    if (name == kExportFormatNames[k]) return ExportFormat(k);
  throw Error("--surface-format '" + printable(name) + "' is not a format (expected ply, obj or vtk)");
}

const char* exportExtension(ExportFormat format) {
  return format == ExportFormat::Vtk ? "vtp" : format == ExportFormat::Ply ? "ply" : "obj";
}

ExportSeries::ExportSeries(std::filesystem::path folder, ExportFormat format)
    : m_folder(std::move(folder)),
      m_format(format),
      m_collection(m_folder / "particles.pvd"),
      m_surfaces(m_folder / "surface.pvd") {
  std::error_code ec;
  std::filesystem::create_directories(m_folder, ec);
  if (ec || !std::filesystem::is_directory(m_folder, ec))
    throw Error("cannot create export folder '" + shownPath(m_folder) +
                "': " + (ec ? ec.message() : std::string("not a folder")));
}

std::filesystem::path ExportSeries::framePath(int frame, bool heightField) const {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.%s", frame, heightField ? "vti" : exportExtension(m_format));
  return m_folder / name;
}

std::filesystem::path ExportSeries::surfacePath(int frame) const {
  char name[40];
  std::snprintf(name, sizeof name, "surface_%05d.%s", frame, exportExtension(m_format));
  return m_folder / name;
}

void ExportSeries::write(int frame, const ExportFrame& data) {
  if (const SurfaceFrame* surface = std::get_if<SurfaceFrame>(&data)) {
    const std::filesystem::path file = surfacePath(frame);
    char comment[64];
    std::snprintf(comment, sizeof comment, "tidepool time %.9g", surface->time);
    if (m_format == ExportFormat::Ply) writePly(file, surface->mesh, surface->time, true);
    if (m_format == ExportFormat::Obj) writeObj(file, surface->mesh, comment);
    if (m_format == ExportFormat::Vtk) {
      writeVtp(file, surface->mesh);
      m_surfaces.add(surface->time, file.filename().string());
    }
  } else if (const HeightField* grid = std::get_if<HeightField>(&data)) {
    if (m_format != ExportFormat::Vtk) throw Error("a heightfield has no PLY form: export it as vtk");
    const std::filesystem::path file = framePath(frame, true);
    writeVti(file, *grid);
    m_collection.add(grid->time, file.filename().string());
  } else {
    const PointCloud& cloud = std::get<PointCloud>(data);
    const std::filesystem::path file = framePath(frame);
    if (m_format == ExportFormat::Obj) throw Error("particles have no OBJ form: export them as vtk or ply");
    if (m_format == ExportFormat::Vtk) {
      writeVtp(file, cloud);
      m_collection.add(cloud.time, file.filename().string());
    } else {
      writePly(file, cloud);
    }
  }
  ++m_written;
}

void ExportSeries::writeObstacles(const TriangleMesh& mesh) {
  if (m_format == ExportFormat::Vtk)
    writeVtp(m_folder / "obstacles.vtp", mesh);
  else if (m_format == ExportFormat::Obj)
    writeObj(m_folder / "obstacles.obj", mesh);
  else
    writePly(m_folder / "obstacles.ply", mesh);
}

}  // namespace tidepool::io
