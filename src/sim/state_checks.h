// Checks of the values a checkpoint sets, beside StateVisitor (sim/model_state.h): a checkpoint's
// framing and checksum say only that the file is as written, so a number a step divides by or
// loops on is checked when it is loaded.
//
//   sim::finiteValue(v, "model.rain_debt", m_rainDebt);  // loading NaN or inf: "entry ... is not a finite number"
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>

#include "base/error.h"
#include "sim/model_state.h"

namespace tidepool::sim {

// Loading: each of the n numbers at x must be finite, else v.fail() naming the entry.
template <class F>
void requireFinite(const StateVisitor& v, const char* name, const F* x, std::size_t n = 1) {
  static_assert(std::is_floating_point_v<F>);
  if (!v.loading()) return;
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(x[i]))
      v.fail(std::string("entry '") + name + "' = " + std::to_string(x[i]) + " is not a finite number");
}

// v.value() of a float or double, or of a glm vector of them, whose every component must be finite.
template <class T>
void finiteValue(StateVisitor& v, const char* name, T& x) {
  v.value(name, x);
  if constexpr (std::is_floating_point_v<T>)
    requireFinite(v, name, &x);
  else
    requireFinite(v, name, &x[0], sizeof(T) / sizeof(x[0]));
}

// The entry "model.capacity" of a particle model whose tap may still add particles (balls, fluid):
// `capacity` is what the parameters' fill and tap need. Loading another value calls
// reallocate(value); more than the parameters need is accepted only as an upload's own count (a
// model that took over another's particles), never beyond the entry "model.count".
template <class Reallocate>
void capacityEntry(StateVisitor& v, std::size_t capacity, Reallocate&& reallocate) {
  std::size_t saved = capacity;
  v.value("model.capacity", saved);
  if (!v.loading() || saved == capacity) return;
  if (saved > capacity) {
    std::uint64_t count = 0;
    v.value("model.count", count);
    if (saved > count)
      v.fail("entry 'model.capacity' = " + std::to_string(saved) + " is more than the parameters' fill and tap (" +
             std::to_string(capacity) + ") and the count (" + std::to_string(count) + ")");
  }
  try {
    reallocate(saved);
  } catch (const Error& e) {
    v.fail(std::string("entry 'model.capacity': ") + e.what());
  }
}

}  // namespace tidepool::sim
