// A ParamVisitor that does nothing: tests derive from it and override only the calls they watch
// (read one key, set one value, add a list item), as the ImGui editor would.
#pragma once

#include "base/param.h"

namespace tidepool::test {

class NullVisitor : public ParamVisitor {
 public:
  void real(const ParamInfo&, float&, float, float) override {}
  void integer(const ParamInfo&, int&, int, int) override {}
  void flag(const ParamInfo&, bool&) override {}
  void text(const ParamInfo&, std::string&) override {}
  void color(const ParamInfo&, glm::vec3&) override {}
  void vector(const ParamInfo&, glm::vec3&, float, float) override {}
  void choiceIndex(const ParamInfo&, int&, std::span<const char* const>) override {}
  bool beginGroup(const ParamInfo&) override { return true; }
  void endGroup() override {}
};

}  // namespace tidepool::test
