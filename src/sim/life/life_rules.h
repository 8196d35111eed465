// The rules of a particle-life system: species, the per-pair force table and the box, exactly
// as lisyarus' web app saves them (shared/SEEDS.md 5.2), so its files load unchanged.
//   After lisyarus, "Particle life" (lisyarus.github.io/webgpu/particle-life.html, 2025).
//
//   Rules r = generateRules({.species = 8, .particleCount = 65536, .seed = 42});
//   std::string code = encodeShareCode(r);      // "AgAAAQAI..." (base64url, version + checksum)
//   Rules same = decodeShareCode(code);         // bit-identical to r
//   io::writeJsonFile("mine.json", rulesToJson(r));
//   Rules back = rulesFromJson(io::readJsonFile("mine.json"), "mine.json");  // throws naming the field
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "io/json.h"

namespace tidepool::life {

constexpr int kMaxSpecies = 20;
constexpr int kMaxParticles = 1 << 24;

// The force species i feels from species j (forces[j] of species i).
struct Force {
  float strength = 0;           // signed; > 0 attracts (units / s^2 at distance 0)
  float collisionStrength = 0;  // repulsion at distance 0; |value| is used (the app tolerates < 0)
  float radius = 0;             // R: the attraction falls linearly to 0 at R (world units)
  float collisionRadius = 0;    // Rc <= R: the repulsion falls linearly to 0 at Rc (world units)
};

struct Species {
  glm::vec3 color{1.0f};      // linear RGB (written as [r, g, b, 1])
  std::vector<Force> forces;  // one per species, in species order
  float spawnWeight = 1;      // relative share of the particles
};

struct Rules {
  int particleCount = 65536;
  std::vector<Species> species;
  glm::vec2 size{1024.0f, 576.0f};  // "simulationSize": the box is [-w/2, w/2] x [-h/2, h/2]
  float friction = 10;              // 1/s: v *= exp(-friction·dt)
  float centralForce = 0;           // 1/s^2: F -= centralForce·p
  bool symmetricForces = false;     // use the average of (i,j) and (j,i)
  bool loopingBorders = false;      // torus (minimum image) instead of reflecting walls
  std::uint32_t seed = 0;           // the generator seed these rules came from

  int speciesCount() const { return int(species.size()); }
  float maxRadius() const;  // largest R in the table (world units)
  bool operator==(const Rules&) const;
};

// What generateRules() takes: the web app's controls.
struct GenerateOptions {
  int species = 8;
  int particleCount = 65536;
  glm::vec2 size{1024.0f, 576.0f};
  float friction = 10, centralForce = 0;
  bool symmetricForces = false, loopingBorders = false;
  std::uint32_t seed = 0;
};

// splitmix32 as the web app writes it in JS: uniform floats in [0, 1) from a 32-bit state.
class SplitMix32 {
 public:
  explicit SplitMix32(std::uint32_t seed) : m_state(seed) {}
  std::uint32_t nextU32() {
    m_state += 0x9e3779b9u;
    std::uint32_t t = m_state ^ (m_state >> 16);
    t *= 0x21f0aaadu;
    t ^= t >> 15;
    t *= 0x735a2d97u;
    return t ^ (t >> 15);
  }
  double next() { return double(nextU32()) / 4294967296.0; }  // [0, 1), a JS number

 private:
  std::uint32_t m_state;
};

// The app's generateSystem (SEEDS.md 5.3): per species, in this order, colour (0.25 + 0.75u)^2.2
// per channel; per target j strength 100·(0.25 + 0.75u)·(u < 0.5 ? 1 : -1), collisionStrength
// (5 + 15u)·|strength|, radius 2 + 30u, collisionRadius u·radius/2; then spawnWeight u. With
// symmetricForces, each pair is then averaged. Computed in double like the JS and rounded to
// float once: same seed, same bits on every machine. Throws Error for species outside [1, 20].
Rules generateRules(const GenerateOptions& options);

// The force table the simulation uses: symmetricForces averages (i,j) and (j,i); |collisionStrength|.
std::vector<Force> effectiveForces(const Rules& rules);  // S·S entries, index i·S + j

// Initial particles (x, y, vx, vy, species) for `rules`, from a splitmix32 stream seeded by
// rules.seed ^ 0x6a09e667 (apart from the rule stream; the web app uses Math.random here, so
// its particles cannot be reproduced): per particle, in this order, species by spawn weight
// (roulette), x, y uniform in the box, vx, vy uniform in ±10.
struct InitialParticle {
  glm::vec2 position, velocity;
  int species;
};
// `stream` 0 is the seed's own start; another draws other positions, species and velocities from the
// same weights (a restart: same rules, new particles).
std::vector<InitialParticle> spawnParticles(const Rules& rules, std::uint32_t stream = 0);

// JSON in the web app's schema. Reading checks every field and names the bad one
// ("mine.json: species[2].forces[1].collisionRadius = 40 is larger than radius = 30"); a failed
// read changes nothing. Optional keys: spawnWeight (1), friction (10), centralForce (0),
// symmetricForces, loopingBorders (false), seed (0).
Rules rulesFromJson(const io::Json& json, const std::string& where);
io::Json rulesToJson(const Rules& rules);
void validateRules(const Rules& rules, const std::string& where);  // the same checks as the reader

// Share code: base64url (no padding) of a little-endian packed form: version byte, count,
// species, size, friction, central force, flags, seed, then (version 1) per species colour,
// weight and forces, and a CRC-32 of everything before it. Rules that are exactly what their
// seed generates use version 2, the header alone (40 characters), and are regenerated on
// decoding. Round trips bit-exactly. Decoding throws Error on a bad alphabet, length, version
// or checksum, and validates like the JSON reader.
std::string encodeShareCode(const Rules& rules);
Rules decodeShareCode(const std::string& code);
bool looksLikeShareCode(const std::string& text);  // base64url alphabet only, not a file name

// A rules JSON file path or a share code (what `--rules` and the scene's "rules" key take).
Rules loadRules(const std::string& pathOrCode);

}  // namespace tidepool::life
