// The ImGui side of ParamVisitor: one widget per declared parameter, tooltips from the help text.
#pragma once

#include <vector>

#include "base/param.h"

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
  bool action(const ParamInfo& info) override;  // a button
  bool beginGroup(const ParamInfo& info) override;
  void endGroup() override;
  // Lists: a tree node with an "Add" button, one node per item with a "Remove" button.
  bool beginList(const ParamInfo& info, std::size_t& size, std::size_t maxSize) override;
  bool beginItem(std::size_t index, const std::string& name) override;
  void endItem() override;
  std::size_t endList() override;

 private:
  void tooltip(const ParamInfo& info);
  bool m_changed = false;
  std::vector<std::size_t> m_remove;  // per open list: the item whose "Remove" was pressed
};

}  // namespace tidepool
