// The ImGui side of ParamVisitor: one widget per declared parameter, tooltips from the help text.
#pragma once

#include "scene/param.h"

namespace tidepool {

class ParamEditor final : public ParamVisitor {
 public:
  bool changed() const { return m_changed; }  // any widget edited during this visit

  void real(const ParamInfo& info, float& value, float min, float max) override;
  void integer(const ParamInfo& info, int& value, int min, int max) override;
  void flag(const ParamInfo& info, bool& value) override;
  void text(const ParamInfo& info, std::string& value) override;
  void color(const ParamInfo& info, glm::vec3& value) override;
  void vector(const ParamInfo& info, glm::vec3& value, float min, float max) override;
  void choiceIndex(const ParamInfo& info, int& index, std::span<const char* const> names) override;
  bool beginGroup(const ParamInfo& info) override;
  void endGroup() override;

 private:
  void tooltip(const ParamInfo& info);
  bool m_changed = false;
};

}  // namespace tidepool
