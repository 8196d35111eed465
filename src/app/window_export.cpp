#include "app/window_export.h"

#include <imgui.h>

#include <array>
#include <cstring>

#include "base/log.h"

namespace tidepool {

WindowExport::Message WindowExport::fail(const std::string& what) {
  if (m_exporter) m_lastWritten = m_exporter->written();
  m_exporter.reset();
  m_mesher.reset();
  log::error(what);
  return {"export stopped: " + what, true};
}

WindowExport::Message WindowExport::start(Stage& stage) {
  try {
    if (m_settings.surface) {
      const std::optional<SurfaceInput> water = stage.surfaceInput();
      if (!water) throw Error("this model has no water: a surface export needs balls or fluid");
      m_mesher = std::make_unique<SurfaceMesher>(m_shaders);
      m_mesher->plan(*water, m_settings.surfaceParams);  // a grid that does not fit, before any file
    } else {
      checkExportable("this model", stage.exportSource(), m_settings.format);
    }
    m_exporter = std::make_unique<ParticleExporter>(m_settings.folder, m_settings.format, m_settings.every);
    m_frame = 0;
    capture(stage, 0);
    m_exporter->writeObstacles(stage.exportObstacles());
  } catch (const Error& e) {
    return fail(e.what());
  }
  return {"exporting to " + std::filesystem::absolute(m_settings.folder).string(), false};
}

WindowExport::Message WindowExport::stop() {
  if (!m_exporter) return {"", false};
  try {
    m_exporter->finish();
  } catch (const Error& e) {
    return fail(e.what());
  }
  Message done{m_exporter->summary(), false};
  log::info(done.text);
  m_lastWritten = m_exporter->written();
  m_exporter.reset();
  m_mesher.reset();
  return done;
}

void WindowExport::capture(Stage& stage, int frame) {
  if (m_mesher) {
    const std::optional<SurfaceInput> water = stage.surfaceInput();
    if (!water) throw Error("this model has no water");
    m_mesher->build(*water, m_settings.surfaceParams);
    m_exporter->capture(frame, stage.simTime(), m_mesher->exportSource());
    return;
  }
  const std::optional<ExportSource> source = stage.exportSource();
  if (!source) throw Error("this model has no particles");
  m_exporter->capture(frame, stage.simTime(), *source);
}

std::optional<WindowExport::Message> WindowExport::afterFrame(Stage& stage, bool stepped) {
  if (!m_exporter) return std::nullopt;
  try {
    if (stepped && m_exporter->due(++m_frame)) capture(stage, m_frame);
    m_exporter->poll();
  } catch (const Error& e) {
    return fail(e.what());
  }
  return std::nullopt;
}

std::optional<WindowExport::Message> drawExportPanel(WindowExport& exporter, Stage& stage) {
  std::optional<WindowExport::Message> message;
  ImGui::Begin("tidepool");
  if (ImGui::CollapsingHeader("Export")) {
    WindowExport::Settings& s = exporter.settings();
    ImGui::BeginDisabled(exporter.running());
    const bool water = stage.surfaceInput().has_value();
    if (water) {
      int what = s.surface ? 1 : 0;
      ImGui::RadioButton("particles", &what, 0);
      ImGui::SameLine();
      ImGui::RadioButton("water surface (mesh)", &what, 1);
      s.surface = what == 1;
    } else {
      s.surface = false;
    }
    int format = int(s.format);
    ImGui::RadioButton("VTK (ParaView)", &format, int(io::ExportFormat::Vtk));
    ImGui::SameLine();
    ImGui::RadioButton("PLY (Blender)", &format, int(io::ExportFormat::Ply));
    if (s.surface) {
      ImGui::SameLine();
      ImGui::RadioButton("OBJ", &format, int(io::ExportFormat::Obj));
    } else if (format == int(io::ExportFormat::Obj)) {
      format = int(io::ExportFormat::Ply);  // OBJ holds meshes only
    }
    s.format = io::ExportFormat(format);
    if (s.surface) {  // the ranges of --surface-resolution, --surface-smoothing and --surface-iso
      ImGui::SetNextItemWidth(120);
      ImGui::SliderInt("resolution", &s.surfaceParams.resolution, 16, 512);
      ImGui::SetNextItemWidth(120);
      ImGui::SliderFloat("smoothing (radii)", &s.surfaceParams.smoothing, 1.0f, 8.0f);
      ImGui::SetNextItemWidth(120);
      ImGui::SliderFloat("iso level", &s.surfaceParams.iso, 0.05f, 0.95f);
    }
    ImGui::SetNextItemWidth(120);
    ImGui::InputInt("every K frames", &s.every);
    s.every = std::max(s.every, 1);
    std::array<char, 512> folder{};
    std::strncpy(folder.data(), s.folder.c_str(), folder.size() - 1);
    if (ImGui::InputText("folder", folder.data(), folder.size())) s.folder = folder.data();
    ImGui::EndDisabled();
    if (!exporter.running()) {
      if (ImGui::Button("Start export")) message = exporter.start(stage);
    } else if (ImGui::Button("Stop export")) {
      message = exporter.stop();
    }
    ImGui::SameLine();
    ImGui::Text("%d frames written%s", exporter.written(), exporter.running() ? " (running)" : "");
  }
  ImGui::End();
  return message;
}

}  // namespace tidepool
