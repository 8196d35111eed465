#include "scene/auto/candidates.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "base/error.h"

namespace tidepool::automethod {

std::string formatValue(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

void write(const Settings& settings, SceneParams& params) {
  for (const Setting& s : settings) s.write(params);
}

Selection selectCheapest(std::vector<Candidate>& candidates, const std::vector<Bound>& bounds,
                         const std::string& where) {
  if (candidates.empty()) throw Error(where + ": no measured setting applies to this scene");
  for (Candidate& c : candidates) {
    if (c.errors.size() != bounds.size()) throw Error(where + ": " + c.label + " lacks a measured error per bound");
    c.guaranteed.assign(bounds.size(), 0.0);
    for (const Candidate& o : candidates)
      if (o.family == c.family && o.step <= c.step)
        for (std::size_t b = 0; b < bounds.size(); ++b)
          c.guaranteed[b] = std::max(c.guaranteed[b], std::isfinite(o.errors[b]) && o.stable ? o.errors[b] : INFINITY);
  }
  Selection s;
  for (const Candidate& c : candidates) {
    if (!c.stable) continue;
    if (!s.mostAccurate || c.errors[0] < s.mostAccurate->errors[0] ||
        (c.errors[0] == s.mostAccurate->errors[0] && c.cost < s.mostAccurate->cost))
      s.mostAccurate = &c;
    bool meets = true;
    for (std::size_t b = 0; b < bounds.size(); ++b) meets = meets && c.guaranteed[b] * kMetricMargin <= bounds[b].value;
    if (meets && (!s.chosen || c.cost < s.chosen->cost)) s.chosen = &c;
  }
  if (s.chosen) return s;
  // Name the first bound that no row meets on its own, with the best row for it.
  for (std::size_t b = 0; b < bounds.size(); ++b) {
    const Candidate* best = nullptr;
    for (const Candidate& c : candidates)
      if (c.stable && (!best || c.guaranteed[b] < best->guaranteed[b] ||
                       (c.guaranteed[b] == best->guaranteed[b] && c.cost < best->cost)))
        best = &c;
    if (!best) break;
    if (best->guaranteed[b] * kMetricMargin > bounds[b].value)
      throw Error(where + "." + bounds[b].key + " " + formatValue(bounds[b].value) +
                  " cannot be met by any measured setting; best is " + best->label + " with " +
                  formatValue(best->guaranteed[b]) + " (needs <= " + formatValue(bounds[b].value / kMetricMargin) +
                  ", the bound over the safety factor " + formatValue(kMetricMargin) + ")");
  }
  if (!s.mostAccurate) throw Error(where + ": every measured setting for this scene was unstable");
  throw Error(where + ": no single measured setting meets all of its bounds together (each alone can be met)");
}

}  // namespace tidepool::automethod
