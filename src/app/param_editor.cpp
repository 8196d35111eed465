#include "app/param_editor.h"

#include <imgui.h>

namespace tidepool {

void ParamEditor::tooltip(const ParamInfo& info) {
  if (info.help && *info.help && ImGui::IsItemHovered()) ImGui::SetTooltip("%s  (%s)", info.help, info.key);
}

void ParamEditor::real(const ParamInfo& info, float& value, float min, float max) {
  // Wide positive ranges (time steps, stiffnesses) are easier to tune on a log scale.
  const ImGuiSliderFlags flags =
      (min > 0 && max / min > 1000.0f ? ImGuiSliderFlags_Logarithmic : 0) | ImGuiSliderFlags_AlwaysClamp;
  m_changed |= ImGui::SliderFloat(info.label, &value, min, max, "%.4g", flags);
  tooltip(info);
}

void ParamEditor::integer(const ParamInfo& info, int& value, int min, int max) {
  const ImGuiSliderFlags flags =
      (min > 0 && max / min > 1000 ? ImGuiSliderFlags_Logarithmic : 0) | ImGuiSliderFlags_AlwaysClamp;
  m_changed |= ImGui::SliderInt(info.label, &value, min, max, "%d", flags);
  tooltip(info);
}

void ParamEditor::flag(const ParamInfo& info, bool& value) {
  m_changed |= ImGui::Checkbox(info.label, &value);
  tooltip(info);
}

void ParamEditor::text(const ParamInfo& info, std::string& value) {
  ImGui::LabelText(info.label, "%s", value.c_str());
  tooltip(info);
}

void ParamEditor::color(const ParamInfo& info, glm::vec3& value) {
  m_changed |= ImGui::ColorEdit3(info.label, &value.x, ImGuiColorEditFlags_Float);
  tooltip(info);
}

void ParamEditor::vector(const ParamInfo& info, glm::vec3& value, float min, float max) {
  m_changed |=
      ImGui::DragFloat3(info.label, &value.x, (max - min) * 0.001f, min, max, "%.3f", ImGuiSliderFlags_AlwaysClamp);
  tooltip(info);
}

void ParamEditor::choiceIndex(const ParamInfo& info, int& index, std::span<const char* const> names) {
  m_changed |= ImGui::Combo(info.label, &index, names.data(), int(names.size()));
  tooltip(info);
}

bool ParamEditor::action(const ParamInfo& info) {
  const bool pressed = ImGui::Button(info.label);
  tooltip(info);
  m_changed |= pressed;
  return pressed;
}

bool ParamEditor::beginGroup(const ParamInfo& info) {
  const bool open = ImGui::TreeNodeEx(info.key, 0, "%s", info.label);  // groups start closed: a compact panel
  tooltip(info);
  return open;
}

void ParamEditor::endGroup() { ImGui::TreePop(); }

bool ParamEditor::beginList(const ParamInfo& info, std::size_t& size, std::size_t maxSize) {
  const bool open = ImGui::TreeNodeEx(info.key, 0, "%s (%zu)", info.label, size);
  tooltip(info);
  if (!open) return false;
  ImGui::BeginDisabled(size >= maxSize);
  if (ImGui::SmallButton("Add")) {
    ++size;
    m_changed = true;
  }
  ImGui::EndDisabled();
  m_remove.push_back(kNoItem);
  return true;
}

bool ParamEditor::beginItem(std::size_t index, const std::string& name) {
  ImGui::PushID(int(index));
  const bool open = ImGui::TreeNodeEx("item", 0, "%s", name.c_str());
  ImGui::SameLine();
  if (ImGui::SmallButton("Remove")) {
    m_remove.back() = index;
    m_changed = true;
  }
  if (!open) ImGui::PopID();
  return open;
}

void ParamEditor::endItem() {
  ImGui::TreePop();
  ImGui::PopID();
}

std::size_t ParamEditor::endList() {
  ImGui::TreePop();
  const std::size_t remove = m_remove.back();
  m_remove.pop_back();
  return remove;
}

}  // namespace tidepool
