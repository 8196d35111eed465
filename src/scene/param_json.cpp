#include "scene/param_json.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <set>
#include <sstream>

#include "base/error.h"

namespace tidepool {
namespace {

std::string formatNumber(double v) {
  if (std::abs(v) < 1e15 && std::floor(v) == v) return std::to_string(static_cast<long long>(v));
  std::ostringstream o;
  o << v;
  return o.str();
}

std::string typeName(const io::Json& j) { return j.type_name(); }

class Reader final : public ParamVisitor {
 public:
  Reader(const io::Json& root, std::string where) : m_where(std::move(where)) {
    if (!root.is_null() && !root.is_object())
      throw Error(m_where + ": expected an object {...}, got " + typeName(root));
    m_stack.push_back({root.is_object() ? &root : nullptr, ""});
  }

  void finish() { checkUnknown(m_stack.back()); }

  void real(const ParamInfo& info, float& value, float min, float max) override {
    if (const io::Json* j = find(info)) value = float(number(*j, info, min, max, true));
  }
  void integer(const ParamInfo& info, int& value, int min, int max) override {
    if (const io::Json* j = find(info)) {
      if (!j->is_number_integer() && !(j->is_number_float() && std::floor(j->get<double>()) == j->get<double>()))
        throw Error(path(info) + ": expected a whole number, got " + io::excerpt(*j));
      value = int(number(*j, info, min, max));
    }
  }
  void flag(const ParamInfo& info, bool& value) override {
    if (const io::Json* j = find(info)) {
      if (!j->is_boolean()) throw Error(path(info) + ": expected true or false, got " + io::excerpt(*j));
      value = j->get<bool>();
    }
  }
  void text(const ParamInfo& info, std::string& value) override {
    if (const io::Json* j = find(info)) {
      if (!j->is_string()) throw Error(path(info) + ": expected a string, got " + io::excerpt(*j));
      value = j->get<std::string>();
    }
  }
  void color(const ParamInfo& info, glm::vec3& value) override {
    if (const io::Json* j = find(info)) value = triple(*j, info, 0.0f, 1.0f);
  }
  void vector(const ParamInfo& info, glm::vec3& value, float min, float max) override {
    if (const io::Json* j = find(info)) value = triple(*j, info, min, max);
  }
  void choiceIndex(const ParamInfo& info, int& index, std::span<const char* const> names) override {
    const io::Json* j = find(info);
    if (!j) return;
    std::string all;
    for (const char* n : names) all += (all.empty() ? "" : ", ") + std::string(n);
    if (!j->is_string()) throw Error(path(info) + ": expected one of " + all + ", got " + io::excerpt(*j));
    for (std::size_t i = 0; i < names.size(); ++i)
      if (j->get<std::string>() == names[i]) {
        index = int(i);
        return;
      }
    throw Error(path(info) + " = '" + io::printable(j->get<std::string>()) + "' is not one of: " + all);
  }
  bool beginGroup(const ParamInfo& info) override {
    const io::Json* j = find(info);
    if (j && !j->is_object()) throw Error(path(info) + ": expected an object {...}, got " + typeName(*j));
    m_stack.push_back({j, m_stack.back().prefix + info.key + "."});
    return true;
  }
  void endGroup() override {
    checkUnknown(m_stack.back());
    m_stack.pop_back();
  }
  bool beginList(const ParamInfo& info, std::size_t& size, std::size_t maxSize) override {
    const io::Json* j = find(info);
    if (j && !j->is_array()) throw Error(path(info) + ": expected an array [{...}, ...], got " + typeName(*j));
    if (j && j->size() > maxSize)
      throw Error(path(info) + ": " + std::to_string(j->size()) + " items, at most " + std::to_string(maxSize));
    if (j) size = j->size();
    m_lists.push_back({j, m_stack.back().prefix + info.key});
    return true;
  }
  bool beginItem(std::size_t index, const std::string&) override {
    const List& list = m_lists.back();
    const std::string at = list.path + "[" + std::to_string(index) + "]";
    const io::Json* item = list.array ? &(*list.array)[index] : nullptr;
    if (item && !item->is_object())
      throw Error(m_where + "." + at + ": expected an object {...}, got " + io::excerpt(*item));
    m_stack.push_back({item, at + "."});
    return true;
  }
  void endItem() override { endGroup(); }
  std::size_t endList() override {
    m_lists.pop_back();
    return kNoItem;
  }

 private:
  struct List {
    const io::Json* array;  // nullptr: absent, the items keep their defaults
    std::string path;       // "group.key"
  };

  struct Level {
    const io::Json* object;  // nullptr: absent, all defaults
    std::string prefix;      // "group." for nested keys
    std::vector<std::string> known{};
  };

  std::string path(const ParamInfo& info) const { return m_where + "." + m_stack.back().prefix + info.key; }

  const io::Json* find(const ParamInfo& info) {
    Level& level = m_stack.back();
    level.known.emplace_back(info.key);
    if (!level.object) return nullptr;
    auto it = level.object->find(info.key);
    return it == level.object->end() ? nullptr : &*it;
  }

  // A float is compared as the float it becomes: 0.05 in a file is the 0.05f a bound is written
  // as, so the bounds hold inclusive and exact.
  double number(const io::Json& j, const ParamInfo& info, double min, double max, bool isFloat = false) const {
    if (!j.is_number()) throw Error(path(info) + ": expected a number, got " + io::excerpt(j));
    const double v = j.get<double>();
    const double stored = isFloat && std::abs(v) <= double(FLT_MAX) ? double(float(v)) : v;
    if (!(stored >= min && stored <= max))
      throw Error(path(info) + " = " + formatNumber(v) + " is out of range [" + formatNumber(min) + ", " +
                  formatNumber(max) + "]");
    return v;
  }

  glm::vec3 triple(const io::Json& j, const ParamInfo& info, float min, float max) const {
    if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number())
      throw Error(path(info) + ": expected an array of 3 numbers, got " + io::excerpt(j));
    glm::vec3 v;
    for (int i = 0; i < 3; ++i) {
      v[i] = j[i].get<float>();
      if (!(v[i] >= min && v[i] <= max))
        throw Error(path(info) + "[" + std::to_string(i) + "] = " + formatNumber(v[i]) + " is out of range [" +
                    formatNumber(min) + ", " + formatNumber(max) + "]");
    }
    return v;
  }

  void checkUnknown(const Level& level) const {
    if (!level.object) return;
    for (const auto& [key, value] : level.object->items()) {
      if (std::find(level.known.begin(), level.known.end(), key) != level.known.end()) continue;
      std::string known;
      for (const std::string& k : level.known) known += (known.empty() ? "" : ", ") + k;
      throw Error(m_where + "." + level.prefix + io::printable(key) +
                  ": unknown key (known here: " + (known.empty() ? "none" : known) + ")");
    }
  }

  std::string m_where;
  std::vector<Level> m_stack;
  std::vector<List> m_lists;
};

class Writer final : public ParamVisitor {
 public:
  io::Json result = io::Json::object();
  void real(const ParamInfo& i, float& v, float, float) override { top()[i.key] = v; }
  void integer(const ParamInfo& i, int& v, int, int) override { top()[i.key] = v; }
  void flag(const ParamInfo& i, bool& v) override { top()[i.key] = v; }
  void text(const ParamInfo& i, std::string& v) override { top()[i.key] = v; }
  void color(const ParamInfo& i, glm::vec3& v) override { top()[i.key] = {v.x, v.y, v.z}; }
  void vector(const ParamInfo& i, glm::vec3& v, float, float) override { top()[i.key] = {v.x, v.y, v.z}; }
  void choiceIndex(const ParamInfo& i, int& index, std::span<const char* const> names) override {
    top()[i.key] = names[std::size_t(index)];
  }
  bool beginGroup(const ParamInfo& i) override {
    m_stack.push_back(&(top()[i.key] = io::Json::object()));
    return true;
  }
  void endGroup() override { m_stack.pop_back(); }
  bool beginList(const ParamInfo& i, std::size_t&, std::size_t) override {
    m_stack.push_back(&(top()[i.key] = io::Json::array()));
    return true;
  }
  bool beginItem(std::size_t, const std::string&) override {
    top().push_back(io::Json::object());
    m_stack.push_back(&top().back());
    return true;
  }
  void endItem() override { m_stack.pop_back(); }
  std::size_t endList() override {
    m_stack.pop_back();
    return kNoItem;
  }

 private:
  // The object or array being written; a parent is not touched while a child is open, so the
  // pointers stay valid.
  io::Json& top() { return *m_stack.back(); }
  std::vector<io::Json*> m_stack{&result};
};

}  // namespace

void readParams(const io::Json& json, const ParamVisit& visit, const std::string& where) {
  Reader reader(json, where);
  visit(reader);
  reader.finish();
}

io::Json writeParams(const ParamVisit& visit) {
  Writer writer;
  visit(writer);
  return writer.result;
}

}  // namespace tidepool
