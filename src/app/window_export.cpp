#include "app/window_export.h"

#include <imgui.h>

#include <array>
#include <cstring>

#include "base/log.h"

namespace tidepool {

WindowExport::Message WindowExport::fail(const std::string& what) {
  if (m_exporter) m_lastWritten = m_exporter->written();
  m_exporter.reset();
  log::error(what);
  return {"export stopped: " + what, true};
}

WindowExport::Message WindowExport::start(Stage& stage) {
  try {
    const std::optional<ExportSource> source = stage.exportSource();
    checkExportable("this model", source, m_settings.format);
    m_exporter = std::make_unique<ParticleExporter>(m_settings.folder, m_settings.format, m_settings.every);
    m_frame = 0;
    m_exporter->capture(0, stage.simTime(), *source);
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
  return done;
}

std::optional<WindowExport::Message> WindowExport::afterFrame(Stage& stage, bool stepped) {
  if (!m_exporter) return std::nullopt;
  try {
    if (stepped && m_exporter->due(++m_frame)) {
      const std::optional<ExportSource> source = stage.exportSource();
      if (!source) throw Error("this model has no particles");
      m_exporter->capture(m_frame, stage.simTime(), *source);
    }
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
    int format = int(s.format);
    ImGui::RadioButton("VTK (ParaView)", &format, int(io::ExportFormat::Vtk));
    ImGui::SameLine();
    ImGui::RadioButton("PLY (Blender)", &format, int(io::ExportFormat::Ply));
    s.format = io::ExportFormat(format);
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
