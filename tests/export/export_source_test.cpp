// The GPU side of the export on llvmpipe: what a model's buffers hold comes out in the file as
// points and fields (fp32 and fp16 storage), and a capture keeps the state of its frame even
// when the model steps before the copy is read back.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <string>

#include "render/particle_exporter.h"
#include "sim/life/life_rules.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

class ExportSourceTest : public test::GlTest {};

// The rows of a PLY file the exporter wrote whose properties are all 4 bytes wide.
std::vector<std::vector<float>> plyRows(const std::filesystem::path& file, std::size_t properties) {
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t body = bytes.find("end_header\n") + 11;
  const std::size_t n = std::stoul(bytes.substr(bytes.find("element vertex ") + 15));
  EXPECT_EQ(bytes.size(), body + n * properties * 4) << file;
  std::vector<std::vector<float>> rows(n, std::vector<float>(properties));
  for (std::size_t i = 0; i < n; ++i)
    std::memcpy(rows[i].data(), bytes.data() + body + i * properties * 4, properties * 4);
  return rows;
}

std::int32_t asInt(float bits) {
  std::int32_t v;
  std::memcpy(&v, &bits, 4);
  return v;
}

}  // namespace

TEST_F(ExportSourceTest, SwarmPointsAreWorldUnitsAtZAndTheCaptureKeepsItsFrame) {
  for (sim::Storage storage : {sim::Storage::Fp32, sim::Storage::Fp16}) {
    SCOPED_TRACE(storage == sim::Storage::Fp16 ? "fp16" : "fp32");
    sim::SwarmParams params;
    params.storage = storage;
    sim::Swarm swarm(shaders(), params);
    swarm.setAspect(2.0);
    const std::vector<sim::SwarmParticle> start = {{{0.5f, -0.25f}, {1.0f, 2.0f}}, {{-1.0f, 0.75f}, {-0.5f, 0.0f}}};
    swarm.upload(start);
    test::TempDir dir;
    ParticleExporter exporter(dir.path(), io::ExportFormat::Ply, 1);
    exporter.capture(0, swarm.time(), swarmSource(swarm, nullptr));
    swarm.step(0.1);  // moves them; the file must still hold frame 0
    exporter.finish();
    ASSERT_EQ(exporter.written(), 1);
    const auto rows = plyRows(dir / "frame_00000.ply", 6);
    ASSERT_EQ(rows.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
      const std::vector<float> expected = {start[i].pos.x * 2.0f, start[i].pos.y, 0.0f,
                                           start[i].vel.x,        start[i].vel.y, 0.0f};
      EXPECT_EQ(rows[i], expected) << "particle " << i;
    }
  }
}

TEST_F(ExportSourceTest, LifeSpeciesAndStateMatchTheModelsBuffers) {
  for (life::Storage storage : {life::Storage::Fp32, life::Storage::Fp16}) {
    SCOPED_TRACE(storage == life::Storage::Fp16 ? "fp16" : "fp32");
    life::Params params;
    params.storage = storage;
    life::Life model(shaders(), life::generateRules({.species = 3, .particleCount = 256, .seed = 4}), params);
    model.stepOnce(1.0f / 60.0f);
    test::TempDir dir;
    ParticleExporter exporter(dir.path(), io::ExportFormat::Ply, 1);
    exporter.capture(0, model.time(), lifeSource(model));
    exporter.finish();
    const auto rows = plyRows(dir / "frame_00000.ply", 7);  // x y z vx vy vz species
    const std::vector<glm::vec4> pos = model.downloadPositions(), vel = model.downloadVelocities();
    ASSERT_EQ(rows.size(), pos.size());
    std::array<int, 3> perSpecies{};
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const std::vector<float> expected = {pos[i].x, pos[i].y, 0.0f, vel[i].x, vel[i].y, 0.0f};
      EXPECT_EQ(std::vector<float>(rows[i].begin(), rows[i].begin() + 6), expected) << "particle " << i;
      const int species = asInt(rows[i][6]);
      EXPECT_EQ(species, int(pos[i].w)) << "particle " << i;
      ASSERT_TRUE(species >= 0 && species < 3) << species;
      ++perSpecies[std::size_t(species)];
    }
    for (int n : perSpecies) EXPECT_GT(n, 0);
  }
}
