// Parameters are declared once, as a visit over a plain struct; that one declaration drives the
// JSON scene loader and its validation messages (scene/param_json.h), the JSON writer, and the
// ImGui editor (app/param_editor.h). A model's Params stays a plain struct with defaults.
//
//   struct Params { float gravity = 9.81f; int substeps = 4; Integrator integrator = Integrator::Verlet; };
//   void visit(ParamVisitor& v, Params& p) {
//     v.real({"gravity", "Gravity", "m/s^2, downwards"}, p.gravity, 0.0f, 100.0f);
//     v.integer({"substeps", "Substeps", "per frame"}, p.substeps, 1, 64);
//     v.choice({"integrator", "Integrator", ""}, p.integrator, kIntegratorNames);  // "verlet" in JSON
//   }
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <span>
#include <string>

namespace tidepool {

struct ParamInfo {
  const char* key;    // JSON key (snake_case)
  const char* label;  // UI label
  const char* help;   // tooltip / docs: meaning and units
};

class ParamVisitor {
 public:
  virtual ~ParamVisitor() = default;
  virtual void real(const ParamInfo& info, float& value, float min, float max) = 0;
  virtual void integer(const ParamInfo& info, int& value, int min, int max) = 0;
  virtual void flag(const ParamInfo& info, bool& value) = 0;
  virtual void text(const ParamInfo& info, std::string& value) = 0;
  virtual void color(const ParamInfo& info, glm::vec3& value) = 0;  // linear RGB in [0,1]
  virtual void vector(const ParamInfo& info, glm::vec3& value, float min, float max) = 0;
  virtual void choiceIndex(const ParamInfo& info, int& index, std::span<const char* const> names) = 0;
  virtual bool beginGroup(const ParamInfo& info) = 0;  // false: skip the group's contents
  virtual void endGroup() = 0;

  // Enumerations are stored as their names ("verlet", not 2).
  template <class E, std::size_t N>
  void choice(const ParamInfo& info, E& value, const std::array<const char*, N>& names) {
    int index = static_cast<int>(value);
    choiceIndex(info, index, std::span<const char* const>(names.data(), N));
    value = static_cast<E>(index);
  }
};

}  // namespace tidepool
