// A scene's "params", typed: one struct per model holding the model's Params and its view's
// (BallsSceneParams: balls::Params + the look and camera). The scene file's "params" object is read
// into it once, when the scene loads (ModelEntry::parse, scene/stage.h: the model's ParamVisitor
// declaration, so errors name the key); "method": "auto" writes its pick into the typed fields;
// the stage is built from it. Held by value, so a Scene copies like any struct.
//
//   const Scene scene = loadScene("assets/scenes/balls-auto.json");
//   const balls::Params& p = scene.params.model<balls::Params>();  // engine.dt, substeps as auto picked
#pragma once

#include <any>
#include <string>
#include <typeinfo>
#include <utility>

#include "base/error.h"
#include "scene/param_json.h"

namespace tidepool {

class SceneParams {
 public:
  SceneParams() = default;  // none: a Scene made in code before its model's params are read
  template <class P>
  explicit SceneParams(P params) : m_value(std::move(params)) {
    if constexpr (requires(P p) { p.model; }) {
      m_modelType = &typeid(decltype(P::model));
      m_model = [](std::any& value) -> void* { return &std::any_cast<P&>(value).model; };
    }
  }

  // The struct of model P; throws Error when these are another model's (or none).
  template <class P>
  P& as() {
    return checked(std::any_cast<P>(&m_value));
  }
  template <class P>
  const P& as() const {
    return checked(std::any_cast<P>(&m_value));
  }
  // The model's own parameters among them (their member `model`: balls::Params, ripples::Params,
  // ...), which method auto edits without knowing the stage's view settings.
  template <class Model>
  Model& model() {
    if (!m_model || *m_modelType != typeid(Model)) throw Error("scene params: these hold no such model parameters");
    return *static_cast<Model*>(m_model(m_value));
  }
  template <class Model>
  bool holds() const {  // whether model<Model>() would succeed
    return m_model && *m_modelType == typeid(Model);
  }
  template <class Model>
  const Model& model() const {
    return const_cast<SceneParams*>(this)->model<Model>();
  }

 private:
  template <class P>
  static P& checked(P* p) {
    if (!p) throw Error("scene params: these are not the parameters of this model");
    return *p;
  }
  std::any m_value;
  const std::type_info* m_modelType = nullptr;  // of the member `model`, when there is one
  void* (*m_model)(std::any& value) = nullptr;  // its address in m_value
};

// Reads a scene's "params" object (null: all defaults) into P through `visit(ParamVisitor&, P&)`,
// validated as readParams does; `where` prefixes messages ("scenes/dam.json: params").
template <class P>
SceneParams readSceneParams(const io::Json& json, const std::string& where) {
  P params;
  readParams(
      json, [&](ParamVisitor& v) { visit(v, params); }, where);
  return SceneParams(std::move(params));
}

}  // namespace tidepool
