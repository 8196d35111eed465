// Share codes and rule loading (life_rules.h): a packed little-endian binary form of the rules,
// base64url encoded, with a version byte and a CRC-32 so a mangled paste is refused, not run.
// Version 1 carries the whole table (~1.6k characters for 8 species); version 2, used whenever
// the rules are exactly what their seed generates, carries only the generator's inputs
// (40 characters) and regenerates the table bit for bit.
#include <cstring>
#include <filesystem>

#include "base/error.h"
#include "io/checkpoint_file.h"  // io::crc32
#include "sim/life/life_rules.h"

namespace tidepool::life {
namespace {

constexpr std::uint8_t kFullTable = 1;  // header + colours, weights and forces
constexpr std::uint8_t kSeeded = 2;     // header only: the rules are generateRules(header)
// The longest code: version 1 with kMaxSpecies species (header 27 bytes, per species colour,
// weight and one force per species, then the CRC), 4 characters per 3 bytes.
constexpr std::size_t kMaxCodeBytes = 27 + kMaxSpecies * (16 + 16 * kMaxSpecies) + 4;
constexpr std::size_t kMaxCodeChars = (kMaxCodeBytes * 4 + 2) / 3;
constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";

class Writer {
 public:
  void u8(std::uint8_t v) { m_bytes.push_back(v); }
  void u32(std::uint32_t v) {
    for (int i = 0; i < 4; ++i) m_bytes.push_back(std::uint8_t(v >> (8 * i)));
  }
  void f32(float v) {
    std::uint32_t bits;
    std::memcpy(&bits, &v, 4);
    u32(bits);
  }
  std::vector<std::uint8_t>& bytes() { return m_bytes; }

 private:
  std::vector<std::uint8_t> m_bytes;
};

class Reader {
 public:
  Reader(const std::vector<std::uint8_t>& bytes, std::size_t end) : m_bytes(bytes), m_end(end) {}
  std::uint8_t u8() {
    need(1);
    return m_bytes[m_pos++];
  }
  std::uint32_t u32() {
    need(4);
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= std::uint32_t(m_bytes[m_pos++]) << (8 * i);
    return v;
  }
  float f32() {
    const std::uint32_t bits = u32();
    float v;
    std::memcpy(&v, &bits, 4);
    return v;
  }
  bool done() const { return m_pos == m_end; }

 private:
  void need(std::size_t n) const {
    if (m_pos + n > m_end) throw Error("share code: too short (truncated when copied?)");
  }
  const std::vector<std::uint8_t>& m_bytes;
  std::size_t m_end, m_pos = 0;
};

int digit(char c) {
  const char* p = std::strchr(kAlphabet, c);
  return c != 0 && p ? int(p - kAlphabet) : -1;
}

}  // namespace

bool looksLikeShareCode(const std::string& text) {
  if (text.size() < 16) return false;
  for (char c : text)
    if (digit(c) < 0) return false;
  return true;
}

GenerateOptions optionsOf(const Rules& r) {
  return {r.speciesCount(), r.particleCount,   r.size,           r.friction,
          r.centralForce,   r.symmetricForces, r.loopingBorders, r.seed};
}

std::string encodeShareCode(const Rules& r) {
  const bool seeded = r.speciesCount() >= 1 && r.speciesCount() <= kMaxSpecies && generateRules(optionsOf(r)) == r;
  Writer w;
  w.u8(seeded ? kSeeded : kFullTable);
  w.u32(std::uint32_t(r.particleCount));
  w.u8(std::uint8_t(r.speciesCount()));
  w.f32(r.size.x);
  w.f32(r.size.y);
  w.f32(r.friction);
  w.f32(r.centralForce);
  w.u8(std::uint8_t((r.symmetricForces ? 1 : 0) | (r.loopingBorders ? 2 : 0)));
  w.u32(r.seed);
  for (const Species& s : seeded ? std::vector<Species>() : r.species) {
    for (int c = 0; c < 3; ++c) w.f32(s.color[c]);
    w.f32(s.spawnWeight);
    for (const Force& f : s.forces) {
      w.f32(f.strength);
      w.f32(f.collisionStrength);
      w.f32(f.radius);
      w.f32(f.collisionRadius);
    }
  }
  std::vector<std::uint8_t>& b = w.bytes();
  w.u32(io::crc32(b));
  std::string out;
  for (std::size_t i = 0; i < b.size(); i += 3) {
    const std::uint32_t n = std::uint32_t(b[i]) << 16 | (i + 1 < b.size() ? std::uint32_t(b[i + 1]) << 8 : 0u) |
                            (i + 2 < b.size() ? std::uint32_t(b[i + 2]) : 0u);
    const std::size_t chars = std::min<std::size_t>(4, (b.size() - i) * 4 / 3 + 1);
    for (std::size_t k = 0; k < chars; ++k) out += kAlphabet[(n >> (18 - 6 * k)) & 63];
  }
  return out;
}

Rules decodeShareCode(const std::string& code) {
  if (code.size() > kMaxCodeChars)
    throw Error("share code: " + std::to_string(code.size()) + " characters, longer than the " +
                std::to_string(kMaxCodeChars) + " of the largest rules (" + std::to_string(kMaxSpecies) + " species)");
  if (code.size() % 4 == 1) throw Error("share code: bad length " + std::to_string(code.size()) + " (truncated?)");
  std::vector<std::uint8_t> b;
  std::uint32_t acc = 0;
  int bits = 0;
  for (std::size_t i = 0; i < code.size(); ++i) {
    const int d = digit(code[i]);
    if (d < 0)
      throw Error("share code: character " + std::to_string(i) + " ('" + io::printable(std::string(1, code[i])) +
                  "') is not base64url (A-Z a-z 0-9 - _)");
    acc = (acc << 6) | std::uint32_t(d);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      b.push_back(std::uint8_t(acc >> bits));
    }
  }
  if (b.size() < 5) throw Error("share code: too short (truncated when copied?)");
  if (b[0] != kFullTable && b[0] != kSeeded)
    throw Error("share code: version " + std::to_string(b[0]) +
                " is not supported (this build reads versions 1 and 2)");
  const std::size_t body = b.size() - 4;
  std::uint32_t stored = 0;
  for (int i = 0; i < 4; ++i) stored |= std::uint32_t(b[body + std::size_t(i)]) << (8 * i);
  if (stored != io::crc32(std::span<const std::uint8_t>(b.data(), body)))
    throw Error("share code: checksum mismatch (the code was altered or cut)");
  Reader in(b, body);
  in.u8();
  Rules r;
  r.particleCount = int(std::min<std::uint32_t>(in.u32(), std::uint32_t(kMaxParticles) + 1));
  const int species = in.u8();
  r.size.x = in.f32();
  r.size.y = in.f32();
  r.friction = in.f32();
  r.centralForce = in.f32();
  const std::uint8_t flags = in.u8();
  r.symmetricForces = flags & 1;
  r.loopingBorders = flags & 2;
  r.seed = in.u32();
  if (species < 1 || species > kMaxSpecies)
    throw Error("share code: species = " + std::to_string(species) + " is out of range [1, " +
                std::to_string(kMaxSpecies) + "]");
  if (b[0] == kSeeded) {
    if (!in.done()) throw Error("share code: unexpected extra bytes after the rules");
    GenerateOptions options = optionsOf(r);
    options.species = species;
    Rules generated = generateRules(options);
    validateRules(generated, "share code");
    return generated;
  }
  r.species.resize(std::size_t(species));
  for (Species& s : r.species) {
    for (int c = 0; c < 3; ++c) s.color[c] = in.f32();
    s.spawnWeight = in.f32();
    s.forces.resize(std::size_t(species));
    for (Force& f : s.forces) f = {in.f32(), in.f32(), in.f32(), in.f32()};
  }
  if (!in.done()) throw Error("share code: unexpected extra bytes after the rules");
  validateRules(r, "share code");
  return r;
}

Rules loadRules(const std::string& pathOrCode) {
  std::error_code ec;
  if (std::filesystem::exists(pathOrCode, ec) || !looksLikeShareCode(pathOrCode))
    return rulesFromJson(io::readJsonFile(pathOrCode), pathOrCode);
  return decodeShareCode(pathOrCode);
}

}  // namespace tidepool::life
