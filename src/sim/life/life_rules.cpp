#include "sim/life/life_rules.h"

#include <array>
#include <cmath>
#include <sstream>

#include "base/error.h"

namespace tidepool::life {
namespace {

std::string number(double v) {
  if (std::abs(v) < 1e15 && std::floor(v) == v) return std::to_string(static_cast<long long>(v));  // 16777216
  std::ostringstream o;
  o << v;
  return o.str();
}

// Required/optional typed fields of one JSON object, each error naming `where.key`.
class Fields {
 public:
  Fields(const io::Json& json, std::string where) : m_json(json), m_where(std::move(where)) {
    if (!json.is_object()) throw Error(m_where + ": expected an object {...}, got " + std::string(json.type_name()));
  }
  std::string path(const char* key) const { return m_where + "." + key; }
  const io::Json* find(const char* key, bool required) const {
    const auto it = m_json.find(key);
    if (it == m_json.end()) {
      if (required) throw Error(path(key) + " is missing");
      return nullptr;
    }
    return &*it;
  }
  float real(const char* key, bool required, float fallback = 0) const {
    const io::Json* j = find(key, required);
    if (!j) return fallback;
    return finite(*j, path(key));
  }
  bool flag(const char* key, bool fallback) const {
    const io::Json* j = find(key, false);
    if (!j) return fallback;
    if (!j->is_boolean()) throw Error(path(key) + ": expected true or false, got " + io::excerpt(*j));
    return j->get<bool>();
  }
  double whole(const char* key, bool required, double min, double max, double fallback = 0) const {
    const io::Json* j = find(key, required);
    if (!j) return fallback;
    const double v = finite(*j, path(key));
    if (std::floor(v) != v || v < min || v > max)
      throw Error(path(key) + " = " + io::excerpt(*j) + ": expected a whole number in [" + number(min) + ", " +
                  number(max) + "]");
    return v;
  }
  static float finite(const io::Json& j, const std::string& where) {
    if (!j.is_number()) throw Error(where + ": expected a number, got " + io::excerpt(j));
    const double v = j.get<double>();
    if (!std::isfinite(v) || !std::isfinite(float(v)))
      throw Error(where + " = " + io::excerpt(j) + " is not a finite number");
    return float(v);
  }

 private:
  const io::Json& m_json;
  std::string m_where;
};

glm::vec2 pair(const io::Json* j, const std::string& where) {
  if (!j->is_array() || j->size() != 2) throw Error(where + ": expected [width, height], got " + io::excerpt(*j));
  return {Fields::finite((*j)[0], where + "[0]"), Fields::finite((*j)[1], where + "[1]")};
}

}  // namespace

float Rules::maxRadius() const {
  float r = 0;
  for (const Species& s : species)
    for (const Force& f : s.forces) r = std::max(r, f.radius);
  return r;
}

bool Rules::operator==(const Rules& o) const {
  if (particleCount != o.particleCount || size != o.size || friction != o.friction || centralForce != o.centralForce ||
      symmetricForces != o.symmetricForces || loopingBorders != o.loopingBorders || seed != o.seed ||
      species.size() != o.species.size())
    return false;
  for (std::size_t i = 0; i < species.size(); ++i) {
    const Species &a = species[i], &b = o.species[i];
    if (a.color != b.color || a.spawnWeight != b.spawnWeight || a.forces.size() != b.forces.size()) return false;
    for (std::size_t j = 0; j < a.forces.size(); ++j) {
      const Force &f = a.forces[j], &g = b.forces[j];
      if (f.strength != g.strength || f.collisionStrength != g.collisionStrength || f.radius != g.radius ||
          f.collisionRadius != g.collisionRadius)
        return false;
    }
  }
  return true;
}

Rules generateRules(const GenerateOptions& o) {
  if (o.species < 1 || o.species > kMaxSpecies)
    throw Error("species = " + std::to_string(o.species) + " is out of range [1, " + std::to_string(kMaxSpecies) + "]");
  Rules r;
  r.particleCount = o.particleCount;
  r.size = o.size;
  r.friction = o.friction;
  r.centralForce = o.centralForce;
  r.symmetricForces = o.symmetricForces;
  r.loopingBorders = o.loopingBorders;
  r.seed = o.seed;
  SplitMix32 rng(o.seed);
  const std::size_t n = std::size_t(o.species);
  // The app's numbers are JS doubles until they reach the GPU: generate (and average) in
  // double, round to float once.
  std::vector<std::array<double, 4>> table(n * n);  // strength, collisionStrength, radius, collisionRadius
  r.species.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    Species& s = r.species[i];
    double c[3];
    for (double& channel : c) channel = std::pow(0.25 + 0.75 * rng.next(), 2.2);
    s.color = {float(c[0]), float(c[1]), float(c[2])};
    for (std::size_t j = 0; j < n; ++j) {
      const double magnitude = 0.25 + 0.75 * rng.next();
      const double strength = 100.0 * magnitude * (rng.next() < 0.5 ? 1.0 : -1.0);
      const double collision = (5.0 + 15.0 * rng.next()) * std::abs(strength);
      const double radius = 2.0 + rng.next() * 30.0;
      const double collisionRadius = rng.next() * 0.5 * radius;
      table[i * n + j] = {strength, collision, radius, collisionRadius};
    }
    s.spawnWeight = float(rng.next());
  }
  if (o.symmetricForces)  // the app's symmetrizeForces: each unordered pair once
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        for (int k = 0; k < 4; ++k)
          table[i * n + j][k] = table[j * n + i][k] = (table[i * n + j][k] + table[j * n + i][k]) / 2.0;
  for (std::size_t i = 0; i < n; ++i) {
    r.species[i].forces.resize(n);
    for (std::size_t j = 0; j < n; ++j) {
      const auto& f = table[i * n + j];
      r.species[i].forces[j] = {float(f[0]), float(f[1]), float(f[2]), float(f[3])};
    }
  }
  return r;
}

std::vector<Force> effectiveForces(const Rules& r) {
  const int n = r.speciesCount();
  std::vector<Force> table(std::size_t(n) * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      Force f = r.species[i].forces[j];
      if (r.symmetricForces) {
        const Force& g = r.species[j].forces[i];
        f = {(f.strength + g.strength) * 0.5f, (f.collisionStrength + g.collisionStrength) * 0.5f,
             (f.radius + g.radius) * 0.5f, (f.collisionRadius + g.collisionRadius) * 0.5f};
      }
      f.collisionStrength = std::abs(f.collisionStrength);
      table[std::size_t(i) * n + j] = f;
    }
  return table;
}

std::vector<InitialParticle> spawnParticles(const Rules& r, std::uint32_t stream) {
  // A stream apart from the rule stream: the seed xor 0x6a09e667 (the fractional bits of sqrt 2);
  // restarts step by the golden-ratio constant.
  SplitMix32 rng(r.seed ^ 0x6a09e667u ^ (stream * 0x9e3779b9u));
  std::vector<double> cumulative;
  double total = 0;
  for (const Species& s : r.species) cumulative.push_back(total += std::max(0.0f, s.spawnWeight));
  std::vector<InitialParticle> out(std::size_t(r.particleCount));
  const int last = r.speciesCount() - 1;
  for (InitialParticle& p : out) {
    int species = 0;
    if (total > 0) {
      const double pick = rng.next() * total;
      while (species < last && cumulative[std::size_t(species)] <= pick) ++species;
    } else {
      species = std::min(int(rng.next() * (last + 1)), last);
    }
    p.species = species;
    p.position = {float((rng.next() - 0.5) * r.size.x), float((rng.next() - 0.5) * r.size.y)};
    p.velocity = {float((rng.next() * 2.0 - 1.0) * 10.0), float((rng.next() * 2.0 - 1.0) * 10.0)};
  }
  return out;
}

void validateRules(const Rules& r, const std::string& where) {
  const auto fail = [&](const std::string& what) { throw Error(where + ": " + what); };
  if (r.particleCount < 1 || r.particleCount > kMaxParticles)
    fail("particleCount = " + std::to_string(r.particleCount) + " is out of range [1, " +
         std::to_string(kMaxParticles) + "]");
  const int n = r.speciesCount();
  if (n < 1 || n > kMaxSpecies)
    fail("species has " + std::to_string(n) + " entries: expected 1 to " + std::to_string(kMaxSpecies));
  if (!(r.size.x > 0 && r.size.y > 0 && std::isfinite(r.size.x) && std::isfinite(r.size.y)))
    fail("simulationSize = [" + number(r.size.x) + ", " + number(r.size.y) + "] must be positive");
  if (!(r.friction >= 0 && std::isfinite(r.friction))) fail("friction = " + number(r.friction) + " must be >= 0");
  if (!std::isfinite(r.centralForce)) fail("centralForce is not a finite number");
  for (int i = 0; i < n; ++i) {
    const Species& s = r.species[std::size_t(i)];
    const std::string sp = "species[" + std::to_string(i) + "]";
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(s.color[c]) || s.color[c] < 0) fail(sp + ".color[" + std::to_string(c) + "] must be >= 0");
    if (!(s.spawnWeight >= 0 && std::isfinite(s.spawnWeight)))
      fail(sp + ".spawnWeight = " + number(s.spawnWeight) + " must be >= 0");
    if (int(s.forces.size()) != n)
      fail(sp + ".forces has " + std::to_string(s.forces.size()) + " entries: expected one per species (" +
           std::to_string(n) + ")");
    for (int j = 0; j < n; ++j) {
      const Force& f = s.forces[std::size_t(j)];
      const std::string fp = sp + ".forces[" + std::to_string(j) + "]";
      if (!std::isfinite(f.strength)) fail(fp + ".strength is not a finite number");
      if (!std::isfinite(f.collisionStrength)) fail(fp + ".collisionStrength is not a finite number");
      if (!(f.radius >= 0 && std::isfinite(f.radius))) fail(fp + ".radius = " + number(f.radius) + " must be >= 0");
      if (!(f.collisionRadius >= 0 && std::isfinite(f.collisionRadius)))
        fail(fp + ".collisionRadius = " + number(f.collisionRadius) + " must be >= 0");
      if (f.collisionRadius > f.radius)
        fail(fp + ".collisionRadius = " + number(f.collisionRadius) + " is larger than radius = " + number(f.radius));
    }
  }
  if (r.loopingBorders && 2.0f * r.maxRadius() > std::min(r.size.x, r.size.y))
    fail("loopingBorders needs simulationSize of at least twice the largest radius (" + number(2 * r.maxRadius()) +
         ") on each axis");
}

Rules rulesFromJson(const io::Json& json, const std::string& where) {
  const Fields top(json, where);
  Rules r;
  r.particleCount = int(top.whole("particleCount", true, 1, kMaxParticles));
  r.size = pair(top.find("simulationSize", true), top.path("simulationSize"));
  r.friction = top.real("friction", false, 10.0f);
  r.centralForce = top.real("centralForce", false, 0.0f);
  r.symmetricForces = top.flag("symmetricForces", false);
  r.loopingBorders = top.flag("loopingBorders", false);
  r.seed = std::uint32_t(top.whole("seed", false, 0, 4294967295.0, 0));
  const io::Json* species = top.find("species", true);
  if (!species->is_array()) throw Error(top.path("species") + ": expected an array, got " + io::excerpt(*species));
  if (species->empty() || species->size() > std::size_t(kMaxSpecies))
    throw Error(top.path("species") + " has " + std::to_string(species->size()) + " entries: expected 1 to " +
                std::to_string(kMaxSpecies));
  for (std::size_t i = 0; i < species->size(); ++i) {
    const std::string sp = top.path("species") + "[" + std::to_string(i) + "]";
    const Fields s((*species)[i], sp);
    Species out;
    const io::Json* color = s.find("color", true);
    if (!color->is_array() || (color->size() != 3 && color->size() != 4))
      throw Error(sp + ".color: expected [r, g, b] or [r, g, b, a], got " + io::excerpt(*color));
    for (int c = 0; c < 3; ++c)
      out.color[c] = Fields::finite((*color)[std::size_t(c)], sp + ".color[" + std::to_string(c) + "]");
    out.spawnWeight = s.real("spawnWeight", false, 1.0f);
    const io::Json* forces = s.find("forces", true);
    if (!forces->is_array()) throw Error(sp + ".forces: expected an array, got " + io::excerpt(*forces));
    for (std::size_t j = 0; j < forces->size(); ++j) {
      const Fields f((*forces)[j], sp + ".forces[" + std::to_string(j) + "]");
      out.forces.push_back({f.real("strength", true), f.real("collisionStrength", true), f.real("radius", true),
                            f.real("collisionRadius", true)});
    }
    r.species.push_back(std::move(out));
  }
  validateRules(r, where);
  return r;
}

io::Json rulesToJson(const Rules& r) {
  io::Json species = io::Json::array();
  for (const Species& s : r.species) {
    io::Json forces = io::Json::array();
    for (const Force& f : s.forces)
      forces.push_back({{"strength", f.strength},
                        {"collisionStrength", f.collisionStrength},
                        {"radius", f.radius},
                        {"collisionRadius", f.collisionRadius}});
    species.push_back({{"color", {s.color.r, s.color.g, s.color.b, 1.0f}},
                       {"forces", std::move(forces)},
                       {"spawnWeight", s.spawnWeight}});
  }
  return {{"particleCount", r.particleCount},       {"species", std::move(species)},
          {"simulationSize", {r.size.x, r.size.y}}, {"friction", r.friction},
          {"centralForce", r.centralForce},         {"symmetricForces", r.symmetricForces},
          {"loopingBorders", r.loopingBorders},     {"seed", r.seed}};
}

}  // namespace tidepool::life
