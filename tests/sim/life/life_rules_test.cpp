// Rules: seeded generation is reproducible and in the article's ranges; JSON and share-code
// round trips are exact; malformed inputs are refused with a message naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "base/error.h"
#include "io/json.h"
#include "sim/life/life_rules.h"
#include "support/error_of.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::life;

namespace {

using tidepool::test::errorOf;

io::Json validJson() { return rulesToJson(generateRules({.species = 3, .particleCount = 1000, .seed = 5})); }

}  // namespace

// The web app's own generator, run under node 20: splitmix32 as written in webgpu/particle-life.html
// (lisyarus/lisyarus.github.io, commit acc99f3), cut from the file and evaluated unchanged:
//   node -e "const h = require('fs').readFileSync('particle-life.html', 'utf8');
//            eval(h.slice(h.indexOf('function splitmix32'), h.indexOf('function randomSeed')));
//            const r = splitmix32(1234); console.log([r(), r(), r()].map(x => x * 2 ** 32));"
// Its outputs are u32 / 2^32, so the u32s below are exact (the fractions print as 0.39212514134123921, ...).
TEST(LifeRules, SplitMix32MatchesTheWebAppsGenerator) {
  struct Stream {
    std::uint32_t seed, outputs[3];
  };
  for (const Stream& s :
       {Stream{0, {1684164658u, 3653269916u, 2939563536u}}, Stream{1, {1580013426u, 350525680u, 3524174333u}},
        Stream{1234, {3112186583u, 2648076444u, 428646200u}},
        Stream{4294967295u, {3950124170u, 4293442868u, 1302505678u}}}) {
    SplitMix32 rng(s.seed);
    for (std::uint32_t want : s.outputs) EXPECT_EQ(rng.nextU32(), want) << "seed " << s.seed;
  }
  EXPECT_EQ(SplitMix32(0).next(), 0.39212514134123921) << "the JS number: u32 / 2^32";
}

// The app's generateSystem for seed 1234 and two species, run as above (the function with
// splitmix32, maxForceRadius = 32 and maxForceStrength = 100 cut from the file), each value
// printed through Math.fround to 9 digits: the float tidepool keeps.
TEST(LifeRules, GenerateRulesMatchesTheWebAppsGenerateSystem) {
  const Rules r = generateRules({.species = 2, .seed = 1234});
  ASSERT_EQ(r.speciesCount(), 2);
  EXPECT_EQ(r.species[0].color, glm::vec3(0.601110399f, 0.474255890f, 0.0842765346f));
  EXPECT_EQ(r.species[1].color, glm::vec3(0.666062295f, 0.701963246f, 0.121386781f));
  EXPECT_EQ(r.species[0].spawnWeight, 0.598267734f);
  EXPECT_EQ(r.species[1].spawnWeight, 0.671472192f);
  const Force want[2][2] = {
      {{36.8033180f, 329.837067f, 17.0202160f, 2.86200500f}, {71.6415253f, 374.846649f, 26.2466679f, 12.9944029f}},
      {{48.8461342f, 326.921234f, 7.57053328f, 3.64583230f}, {43.5474777f, 319.027740f, 3.69282246f, 0.362164468f}}};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const Force& f = r.species[i].forces[j];
      SCOPED_TRACE("force " + std::to_string(i) + " <- " + std::to_string(j));
      EXPECT_EQ(f.strength, want[i][j].strength);
      EXPECT_EQ(f.collisionStrength, want[i][j].collisionStrength);
      EXPECT_EQ(f.radius, want[i][j].radius);
      EXPECT_EQ(f.collisionRadius, want[i][j].collisionRadius);
    }
}

TEST(LifeRules, SameSeedSameRulesAndParticles) {
  const GenerateOptions o{.species = 8, .particleCount = 4096, .seed = 1234};
  const Rules a = generateRules(o), b = generateRules(o);
  EXPECT_TRUE(a == b);
  const auto pa = spawnParticles(a), pb = spawnParticles(b);
  ASSERT_EQ(pa.size(), 4096u);
  for (std::size_t i = 0; i < pa.size(); ++i) {
    ASSERT_EQ(pa[i].position, pb[i].position);
    ASSERT_EQ(pa[i].velocity, pb[i].velocity);
    ASSERT_EQ(pa[i].species, pb[i].species);
  }
  EXPECT_FALSE(a == generateRules({.species = 8, .particleCount = 4096, .seed = 1235}));
}

TEST(LifeRules, GeneratedValuesAreInTheArticlesRanges) {
  const Rules r = generateRules({.species = 20, .seed = 99});
  for (const Species& s : r.species) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_GE(s.color[c], std::pow(0.25f, 2.2f) - 1e-6f);
      EXPECT_LE(s.color[c], 1.0f);
    }
    EXPECT_GE(s.spawnWeight, 0.0f);
    EXPECT_LT(s.spawnWeight, 1.0f);
    for (const Force& f : s.forces) {
      EXPECT_GE(std::abs(f.strength), 25.0f - 1e-4f);
      EXPECT_LE(std::abs(f.strength), 100.0f);
      EXPECT_GE(f.collisionStrength, 5.0f * std::abs(f.strength) * (1 - 1e-6f));
      EXPECT_LE(f.collisionStrength, 20.0f * std::abs(f.strength) * (1 + 1e-6f));
      EXPECT_GE(f.radius, 2.0f);
      EXPECT_LE(f.radius, 32.0f);
      EXPECT_LE(f.collisionRadius, 0.5f * f.radius);
    }
  }
  for (const InitialParticle& p : spawnParticles(r)) {
    EXPECT_LE(std::abs(p.position.x), 512.0f);
    EXPECT_LE(std::abs(p.position.y), 288.0f);
    EXPECT_LE(std::abs(p.velocity.x), 10.0f);
  }
}

TEST(LifeRules, SymmetricGenerationAveragesPairs) {
  const Rules r = generateRules({.species = 5, .symmetricForces = true, .seed = 3});
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      EXPECT_EQ(r.species[i].forces[j].strength, r.species[j].forces[i].strength);
      EXPECT_EQ(r.species[i].forces[j].collisionRadius, r.species[j].forces[i].collisionRadius);
    }
}

TEST(LifeRules, JsonRoundTripIsExact) {
  for (bool looping : {false, true}) {
    const Rules r = generateRules(
        {.species = 7, .particleCount = 3000, .centralForce = 0.3f, .loopingBorders = looping, .seed = 77});
    const std::string text = rulesToJson(r).dump(2);
    EXPECT_TRUE(rulesFromJson(io::parseJson(text, "mem"), "mem") == r);
  }
}

TEST(LifeRules, ShareCodeRoundTripIsExact) {
  const Rules r = generateRules({.species = 20,
                                 .particleCount = 1 << 20,
                                 .friction = 3.5f,
                                 .symmetricForces = true,
                                 .loopingBorders = true,
                                 .seed = 0xdeadbeef});
  const std::string code = encodeShareCode(r);
  EXPECT_TRUE(looksLikeShareCode(code));
  EXPECT_EQ(code.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_"),
            std::string::npos);
  EXPECT_TRUE(decodeShareCode(code) == r);
  EXPECT_TRUE(loadRules(code) == r);
  EXPECT_LE(code.size(), 48u) << "rules straight from their seed share as the generator's inputs";
  // Edited rules carry their whole table, still bit-exact.
  Rules edited = r;
  edited.species[3].forces[7].strength = -12.345678f;
  edited.species[19].color = {0.1f, 0.2f, 0.3f};
  const std::string full = encodeShareCode(edited);
  EXPECT_GT(full.size(), 1000u);
  EXPECT_TRUE(decodeShareCode(full) == edited);
  EXPECT_FALSE(decodeShareCode(full) == r);
  // One changed character or a cut code is refused, never half-loaded.
  std::string bad = code;
  bad[20] = bad[20] == 'A' ? 'B' : 'A';
  EXPECT_NE(errorOf([&] { decodeShareCode(bad); }).find("checksum"), std::string::npos);
  EXPECT_NE(errorOf([&] { decodeShareCode(code.substr(0, code.size() - 7)); }).find("share code"), std::string::npos);
  EXPECT_NE(errorOf([&] { decodeShareCode(code.substr(0, 30) + "!" + code.substr(31)); }).find("base64url"),
            std::string::npos);
}

TEST(LifeRules, LoadsTheWebAppsFileFormat) {
  // As the web app saves it: colour with alpha, optional keys absent.
  const std::string text = R"({ "particleCount": 2048, "simulationSize": [1024, 576], "seed": 17,
    "species": [ { "color": [1, 0.5, 0.25, 1], "spawnWeight": 0.5,
                   "forces": [ { "strength": 40, "collisionStrength": -300, "radius": 20, "collisionRadius": 5 } ] } ] })";
  const Rules r = rulesFromJson(io::parseJson(text, "app.json"), "app.json");
  EXPECT_EQ(r.particleCount, 2048);
  EXPECT_EQ(r.friction, 10.0f);
  EXPECT_FALSE(r.loopingBorders);
  EXPECT_EQ(r.species[0].forces[0].collisionStrength, -300.0f);
  EXPECT_EQ(effectiveForces(r)[0].collisionStrength, 300.0f);  // the app uploads |collisionStrength|
}

TEST(LifeRules, MalformedInputsNameTheField) {
  struct Case {
    std::function<void(io::Json&)> edit;
    std::string message;
  };
  const std::vector<Case> cases = {
      {[](io::Json& j) { j["particleCount"] = "many"; }, "x.particleCount: expected a number"},
      {[](io::Json& j) { j.erase("species"); }, "x.species is missing"},
      {[](io::Json& j) { j["species"] = io::Json::array(); }, "x.species has 0 entries: expected 1 to 20"},
      {[](io::Json& j) {
         for (int i = 0; i < 18; ++i) j["species"].push_back(j["species"][0]);
       },
       "x.species has 21 entries"},
      {[](io::Json& j) { j["species"][1]["forces"][2]["radius"] = -1; },
       "x: species[1].forces[2].radius = -1 must be >= 0"},
      {[](io::Json& j) { j["species"][0]["forces"][1]["collisionRadius"] = 1e3; },
       "x: species[0].forces[1].collisionRadius = 1000 is larger than radius"},
      {[](io::Json& j) { j["species"][2]["forces"][0].erase("strength"); },
       "x.species[2].forces[0].strength is missing"},
      {[](io::Json& j) { j["species"][2]["forces"][0]["strength"] = 1e300; },
       "x.species[2].forces[0].strength = 1e+300 is not a finite number"},
      {[](io::Json& j) { j["species"][0]["forces"].erase(0); }, "x: species[0].forces has 2 entries"},
      {[](io::Json& j) { j["simulationSize"] = {1024}; }, "x.simulationSize: expected [width, height]"},
      {[](io::Json& j) { j["loopingBorders"] = 1; }, "x.loopingBorders: expected true or false"},
      {[](io::Json& j) { j["species"][0]["color"] = "red"; }, "x.species[0].color: expected [r, g, b]"},
  };
  for (const Case& c : cases) {
    io::Json j = validJson();
    c.edit(j);
    const std::string message = errorOf([&] { rulesFromJson(j, "x"); });
    EXPECT_NE(message.find(c.message), std::string::npos) << "got: " << message << "\nwanted: " << c.message;
  }
  EXPECT_NE(errorOf([] { generateRules({.species = 0}); }).find("species = 0 is out of range"), std::string::npos);
}

TEST(LifeRules, NaNIsRefusedNamingTheField) {
  // JSON text cannot spell NaN, but a full-table share code (valid checksum) or an edited table can.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  Rules r = generateRules({.species = 3, .particleCount = 1000, .seed = 5});
  r.species[1].forces[2].strength = nan;
  const std::string code = encodeShareCode(r);
  EXPECT_NE(errorOf([&] { decodeShareCode(code); }).find("share code: species[1].forces[2].strength is not a finite"),
            std::string::npos);
  r.species[1].forces[2].strength = 1.0f;
  r.species[0].forces[0].collisionRadius = nan;
  EXPECT_NE(errorOf([&] { validateRules(r, "x"); }).find("x: species[0].forces[0].collisionRadius = "),
            std::string::npos);
  r.species[0].forces[0].collisionRadius = 1.0f;
  r.friction = nan;
  EXPECT_NE(errorOf([&] { decodeShareCode(encodeShareCode(r)); }).find("share code: friction = "), std::string::npos);
}

TEST(LifeRules, PresetsLoadAndAreWhatTheirSeedGenerates) {
  // assets/rules/*.json come from scripts/make_life_rules.py, a Python port of the generator:
  // equality here also shows that the generation is reproducible outside this program.
  int count = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::path(TIDEPOOL_SOURCE_DIR) / "assets/rules")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    const Rules r = loadRules(entry.path().string());
    const Rules again = generateRules({r.speciesCount(), r.particleCount, r.size, r.friction, r.centralForce,
                                       r.symmetricForces, r.loopingBorders, r.seed});
    EXPECT_TRUE(r == again);
    ++count;
  }
  EXPECT_GE(count, 3);
}

TEST(LifeRules, ShareCodeOfThePresetIsStable) {
  // The 'cells' preset (seed 2, 8 species, 16384 particles in 512 x 288): a version-2 code,
  // computed independently with Python's struct, zlib.crc32 and base64.urlsafe_b64encode.
  const Rules cells = loadRules(std::string(TIDEPOOL_SOURCE_DIR) + "/assets/rules/cells.json");
  EXPECT_EQ(encodeShareCode(cells), "AgBAAAAIAAAARAAAkEMAACBBAAAAAAACAAAAsuj5Hg");
}
