// Parameters are declared once, as a visit over a plain struct; that one declaration drives the
// JSON scene loader and its validation messages (scene/param_json.h), the JSON writer, and the
// ImGui editor (app/param_editor.h). A model's Params stays a plain struct with defaults.
//
//   struct Params { float gravity = 9.81f; int substeps = 4; Integrator integrator = Integrator::Verlet; };
//   void visit(ParamVisitor& v, Params& p) {
//     v.real({"gravity", "Gravity", "m/s^2, downwards"}, p.gravity, 0.0f, 100.0f);
//     v.integer({"substeps", "Substeps", "per frame"}, p.substeps, 1, 64);
//     v.choice({"integrator", "Integrator", ""}, p.integrator, kIntegratorNames);  // "verlet" in JSON
//     v.list({"walls", "Walls", "one group each"}, p.walls, 8, [](ParamVisitor& v, Wall& w) {  // [{...}, ...]
//       v.real({"height", "Height", "m"}, w.height, 0.0f, 1.0f);                        // walls[1].height
//     });
//   }
#pragma once

#include <array>
#include <cstddef>
#include <glm/glm.hpp>
#include <span>
#include <string>
#include <utility>
#include <vector>

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
  // A button (the editor): true the frame it is pressed; readers and writers have nothing to do.
  virtual bool action(const ParamInfo& /*info*/) { return false; }
  virtual bool beginGroup(const ParamInfo& info) = 0;  // false: skip the group's contents
  virtual void endGroup() = 0;

  // A list of groups (JSON: an array of objects, "key[2].field" in messages). beginList may change
  // `size` (the reader: the array's length; the editor: its "Add" button) and the list is resized
  // to it, new items taking their defaults; then each item is visited between beginItem and
  // endItem, and endList may name one item to remove (the editor's "Remove"), else kNoItem. A
  // false from beginList or beginItem skips the contents and the matching end call. The defaults
  // visit every item and change nothing, for visitors that only look at the values.
  static constexpr std::size_t kNoItem = ~std::size_t(0);
  virtual bool beginList(const ParamInfo& info, std::size_t& size, std::size_t maxSize);
  virtual bool beginItem(std::size_t index, const std::string& name);  // name: how the UI titles it
  virtual void endItem() {}
  virtual std::size_t endList() { return kNoItem; }

  // `visitItem(ParamVisitor&, T&)` declares an item's parameters; `name(index, const T&)` titles it
  // in the UI (default: its index).
  template <class T, class VisitItem, class Name>
  void list(const ParamInfo& info, std::vector<T>& items, std::size_t maxSize, VisitItem&& visitItem, Name&& name) {
    std::size_t size = items.size();
    const bool open = beginList(info, size, maxSize);
    items.resize(size < maxSize ? size : maxSize);
    if (!open) return;
    for (std::size_t i = 0; i < items.size(); ++i)
      if (beginItem(i, name(i, std::as_const(items[i])))) {
        visitItem(*this, items[i]);
        endItem();
      }
    if (const std::size_t remove = endList(); remove < items.size())
      items.erase(items.begin() + std::ptrdiff_t(remove));
  }
  template <class T, class VisitItem>
  void list(const ParamInfo& info, std::vector<T>& items, std::size_t maxSize, VisitItem&& visitItem) {
    list(info, items, maxSize, visitItem, [](std::size_t i, const T&) { return std::to_string(i); });
  }

  // A double shown, read and range-checked as a float; it changes only when a visitor changes
  // that float, so a default of 1/30 s stays 1/30 rather than 0.033333335.
  void realDouble(const ParamInfo& info, double& value, float min, float max) {
    float f = float(value);
    real(info, f, min, max);
    if (f != float(value)) value = f;
  }

  // Enumerations are stored as their names ("verlet", not 2).
  template <class E, std::size_t N>
  void choice(const ParamInfo& info, E& value, const std::array<const char*, N>& names) {
    int index = static_cast<int>(value);
    choiceIndex(info, index, std::span<const char* const>(names.data(), N));
    value = static_cast<E>(index);
  }
};

inline bool ParamVisitor::beginList(const ParamInfo&, std::size_t&, std::size_t) { return true; }
inline bool ParamVisitor::beginItem(std::size_t, const std::string&) { return true; }

}  // namespace tidepool
