// The window's export: the panel's "Export" section (drawExportPanel) sets what (the particles,
// or for balls and fluid the water surface as a mesh), the format, every K and the folder, and
// starts or stops it; after each frame the simulation advanced, the due frames are captured
// (render/particle_exporter.h; a surface is meshed first, render/surface_mesher.h) and what has
// come back is written.
// Frames count from the start of the export (frame_00000 is the state when Start was pressed).
// A failure (a folder that cannot be made, a full disk, a model without particles) stops the
// export with a message for the panel, never an exception: the simulation runs on.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "render/particle_exporter.h"
#include "render/surface_mesher.h"
#include "scene/stage.h"

namespace tidepool {

class WindowExport {
 public:
  struct Settings {
    io::ExportFormat format = io::ExportFormat::Vtk;  // Obj: surfaces only
    int every = 10;                                   // frames
    std::string folder = "export";                    // relative to the working folder
    bool surface = false;                             // the water surface instead of the particles
    SurfaceParams surfaceParams;
  };

  explicit WindowExport(gl::ShaderLibrary& shaders) : m_shaders(shaders) {}
  struct Message {
    std::string text;  // for the panel
    bool error = false;
  };

  Settings& settings() { return m_settings; }  // the panel's fields; read at start()
  bool running() const { return m_exporter != nullptr; }
  int written() const { return m_exporter ? m_exporter->written() : m_lastWritten; }
  int frame() const { return m_frame; }  // frames since start()

  Message start(Stage& stage);  // captures the state now as frame 0
  Message stop();               // writes the copies still in flight
  // After a frame; `stepped`: the simulation advanced (paused frames export nothing).
  std::optional<Message> afterFrame(Stage& stage, bool stepped);

 private:
  Message fail(const std::string& what);
  void capture(Stage& stage, int frame);  // the particles, or the surface meshed now; throws Error

  gl::ShaderLibrary& m_shaders;
  Settings m_settings;
  std::unique_ptr<ParticleExporter> m_exporter;
  std::unique_ptr<SurfaceMesher> m_mesher;  // surface exports
  int m_frame = 0, m_lastWritten = 0;
};

// The "Export" section of the main panel (appends to the "tidepool" window). Returns a message
// for the panel when the user started or stopped the export.
std::optional<WindowExport::Message> drawExportPanel(WindowExport& exporter, Stage& stage);

}  // namespace tidepool
