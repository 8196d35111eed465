// Every field of every exported file against the model's buffers read back: each model that
// exports (balls, fluid, life and swarm as PLY and VTK points, ripples as a VTK heightfield) is
// stepped, exported once through ParticleExporter, and the files are read back by a small
// independent reader (PLY properties by name; VTK arrays by name through their appended
// offsets). The points and each field must hold exactly what the model's buffers hold, and the
// files no field beyond those listed here.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <map>
#include <regex>
#include <string>

#include "render/particle_exporter.h"
#include "sim/balls/balls.h"
#include "sim/life/life_rules.h"
#include "support/balls_fixtures.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {

class ExportFieldsTest : public test::GlTest {};

using Columns = std::map<std::string, std::vector<float>>;  // a property or array component -> values

std::string readFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The vertex properties of a binary little-endian PLY, by name (ints and bytes as floats).
Columns readPly(const std::filesystem::path& file) {
  const std::string bytes = readFile(file);
  const std::size_t body = bytes.find("end_header\n") + 11;
  std::istringstream header(bytes.substr(0, body));
  std::vector<std::pair<std::string, std::string>> properties;  // type, name
  std::size_t n = 0;
  for (std::string line; std::getline(header, line);) {
    std::istringstream words(line);
    std::string word, type, name;
    words >> word;
    if (word == "element") words >> name >> n;
    if (word == "property" && words >> type >> name) properties.emplace_back(type, name);
  }
  Columns out;
  std::size_t at = body;
  for (std::size_t i = 0; i < n; ++i)
    for (const auto& [type, name] : properties) {
      float v = 0;
      if (type == "float") std::memcpy(&v, bytes.data() + at, 4);
      if (type == "int") {
        std::int32_t k;
        std::memcpy(&k, bytes.data() + at, 4);
        v = float(k);
      }
      if (type == "uchar") v = float(std::uint8_t(bytes[at]));
      EXPECT_TRUE(type == "float" || type == "int" || type == "uchar") << type;
      at += type == "uchar" ? 1 : 4;
      out[name].push_back(v);
    }
  EXPECT_EQ(at, bytes.size()) << file << ": bytes after the last vertex";
  return out;
}

// The appended arrays of a .vtp or .vti, component by component: "velocity.1" is vy; the points
// are "Points.0" ... "Points.2". The cells' connectivity and offsets are left out.
Columns readVtk(const std::filesystem::path& file) {
  const std::string text = readFile(file);
  const std::size_t base = text.find('_', text.find("<AppendedData encoding=\"raw\">")) + 1;
  const std::regex array(
      "<DataArray type=\"(\\w+)\" Name=\"(\\w+)\" NumberOfComponents=\"(\\d+)\" format=\"appended\" "
      "offset=\"(\\d+)\"/>");
  Columns out;
  for (auto it = std::sregex_iterator(text.begin(), text.begin() + std::ptrdiff_t(base), array);
       it != std::sregex_iterator(); ++it) {
    const std::string type = (*it)[1], name = (*it)[2];
    if (name == "connectivity" || name == "offsets") continue;
    const std::size_t components = std::stoul((*it)[3]), at = base + std::stoul((*it)[4]);
    std::uint64_t bytes;
    std::memcpy(&bytes, text.data() + at, 8);
    const std::size_t size = type == "UInt8" ? 1 : 4, values = bytes / size;
    for (std::size_t k = 0; k < values; ++k) {
      const char* p = text.data() + at + 8 + k * size;
      float v = 0;
      if (type == "Float32") std::memcpy(&v, p, 4);
      if (type == "Int32") {
        std::int32_t i;
        std::memcpy(&i, p, 4);
        v = float(i);
      }
      if (type == "UInt8") v = float(std::uint8_t(*p));
      out[name + "." + std::to_string(k % components)].push_back(v);
    }
  }
  return out;
}

// One frame of `source` written as `format` into `dir`; the file's columns.
Columns exportOnce(const ExportSource& source, io::ExportFormat format, double time) {
  test::TempDir dir;
  ParticleExporter exporter(dir.path(), format, 1);
  exporter.capture(0, time, source);
  exporter.finish();
  EXPECT_EQ(exporter.written(), 1);
  for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
    if (entry.path().stem() == "frame_00000")
      return format == io::ExportFormat::Ply ? readPly(entry.path()) : readVtk(entry.path());
  ADD_FAILURE() << "no frame_00000 in " << dir.path();
  return {};
}

// The expected values of each column, in the PLY's names; `vtk` maps them to the VTK arrays'.
struct Expected {
  Columns columns;
  void add(const std::string& name, float v) { columns[name].push_back(v); }
};

const std::map<std::string, std::string> kVtkName = {
    {"x", "Points.0"},        {"y", "Points.1"},
    {"z", "Points.2"},        {"vx", "velocity.0"},
    {"vy", "velocity.1"},     {"vz", "velocity.2"},
    {"foam", "foam.0"},       {"density", "density.0"},
    {"species", "species.0"}, {"red", "color.0"},
    {"green", "color.1"},     {"blue", "color.2"},
    {"height", "height.0"},   {"vertical_velocity", "vertical_velocity.0"}};

// Bit for bit (NaN equal to NaN), and no column more or less.
void expectColumns(const Columns& got, const Expected& want, bool vtk) {
  std::map<std::string, std::vector<float>> named;
  for (const auto& [name, values] : want.columns) named[vtk ? kVtkName.at(name) : name] = values;
  std::vector<std::string> gotNames, wantNames;
  for (const auto& [name, values] : got) gotNames.push_back(name);
  for (const auto& [name, values] : named) wantNames.push_back(name);
  EXPECT_EQ(gotNames, wantNames) << (vtk ? "VTK" : "PLY") << ": the fields written";
  for (const auto& [name, values] : named) {
    const auto it = got.find(name);
    if (it == got.end()) continue;
    ASSERT_EQ(it->second.size(), values.size()) << name;
    std::size_t differing = 0, first = values.size();
    for (std::size_t i = 0; i < values.size(); ++i)
      if (std::memcmp(&it->second[i], &values[i], 4) != 0 && !(std::isnan(it->second[i]) && std::isnan(values[i]))) {
        ++differing;
        first = std::min(first, i);
      }
    EXPECT_EQ(differing, 0u) << (vtk ? "VTK " : "PLY ") << name << ": " << differing << " of " << values.size()
                             << " values differ from the model's buffer, first at " << first << " ("
                             << (first < values.size() ? it->second[first] : 0.0f) << " for "
                             << (first < values.size() ? values[first] : 0.0f) << ")";
  }
}

void expectBothFormats(const ExportSource& source, const Expected& want, double time, bool pointsToo = true) {
  if (pointsToo) {
    SCOPED_TRACE("ply");
    expectColumns(exportOnce(source, io::ExportFormat::Ply, time), want, false);
  }
  SCOPED_TRACE("vtk");
  expectColumns(exportOnce(source, io::ExportFormat::Vtk, time), want, true);
}

// Particle water: x y z from the positions, vx vy vz and foam from the velocities.
Expected waterExpected(const std::vector<glm::vec4>& pos, const std::vector<glm::vec4>& vel) {
  Expected e;
  for (std::size_t i = 0; i < pos.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      e.add(std::string(1, "xyz"[k]), pos[i][k]);
      e.add(std::string("v") + "xyz"[k], vel[i][k]);
    }
    e.add("foam", vel[i].w);
  }
  return e;
}

}  // namespace

TEST_F(ExportFieldsTest, BallsPositionsVelocitiesAndFoamAreTheModelsBuffers) {
  balls::Params p = test::emptyTank();
  p.fill = water::Fill::Block;
  p.fillMax = glm::vec3(0.2f, 0.3f, 0.3f);
  balls::Balls b(shaders(), p);
  for (int k = 0; k < 20; ++k) b.stepOnce();  // falling: velocities and foam
  const std::vector<glm::vec4> pos = b.downloadPositions(), vel = b.downloadVelocities();
  ASSERT_GT(pos.size(), 100u);
  expectBothFormats(waterSource(b), waterExpected(pos, vel), b.time());
}

TEST_F(ExportFieldsTest, FluidFieldsAndDensityAreTheModelsBuffers) {
  fluid::Params p;
  p.setSpacing(0.02f);
  p.domainMax = glm::vec3(0.2f, 0.16f, 0.3f);
  p.fill = water::Fill::Block;
  p.fillMax = glm::vec3(0.1f, 0.16f, 0.2f);
  p.restDensity = 997.0f;
  fluid::Fluid f(shaders(), p);
  for (int k = 0; k < 5; ++k) f.stepOnce();
  ASSERT_TRUE(f.densitiesValid());
  const std::vector<glm::vec4> pos = f.downloadPositions(), vel = f.downloadVelocities();
  const std::vector<glm::vec2> density = f.densities().read<glm::vec2>(pos.size());
  Expected e = waterExpected(pos, vel);
  for (const glm::vec2& d : density) e.add("density", p.restDensity * d.y);
  expectBothFormats(fluidSource(f), e, f.time());
}

TEST_F(ExportFieldsTest, LifeVelocityAndSpeciesAreTheModelsBuffers) {
  for (life::Storage storage : {life::Storage::Fp32, life::Storage::Fp16}) {
    SCOPED_TRACE(storage == life::Storage::Fp16 ? "fp16" : "fp32");
    life::Params params;
    params.storage = storage;
    life::Life model(shaders(), life::generateRules({.species = 3, .particleCount = 300, .seed = 5}), params);
    for (int k = 0; k < 3; ++k) model.stepOnce(1.0f / 60.0f);
    const std::vector<glm::vec4> pos = model.downloadPositions(), vel = model.downloadVelocities();
    Expected e;
    for (std::size_t i = 0; i < pos.size(); ++i) {
      e.add("x", pos[i].x), e.add("y", pos[i].y), e.add("z", 0.0f);
      e.add("vx", vel[i].x), e.add("vy", vel[i].y), e.add("vz", 0.0f);
      e.add("species", pos[i].w);
    }
    expectBothFormats(lifeSource(model), e, model.time());
  }
}

TEST_F(ExportFieldsTest, SwarmWorldPointsVelocityAndColourAreTheModelsBuffers) {
  for (sim::Storage storage : {sim::Storage::Fp32, sim::Storage::Fp16}) {
    SCOPED_TRACE(storage == sim::Storage::Fp16 ? "fp16" : "fp32");
    sim::SwarmParams params;
    params.storage = storage;
    params.particles = 500;
    sim::Swarm swarm(shaders(), params);
    swarm.setAspect(1.5);
    swarm.step(0.05);
    const std::vector<sim::SwarmParticle> state = swarm.download();
    // A colour per particle as the renderer packs it (packUnorm4x8): byte k of particle i.
    std::vector<std::uint32_t> packed(state.size());
    for (std::size_t i = 0; i < packed.size(); ++i) packed[i] = std::uint32_t(i * 2654435761u);
    const gl::Buffer colors{std::span<const std::uint32_t>(packed)};
    Expected e;
    for (std::size_t i = 0; i < state.size(); ++i) {
      e.add("x", state[i].pos.x * 1.5f), e.add("y", state[i].pos.y), e.add("z", 0.0f);
      e.add("vx", state[i].vel.x), e.add("vy", state[i].vel.y), e.add("vz", 0.0f);
      for (int k = 0; k < 3; ++k)
        e.add(std::string(k == 0 ? "red" : k == 1 ? "green" : "blue"), float((packed[i] >> (8 * k)) & 0xffu));
    }
    expectBothFormats(swarmSource(swarm, &colors), e, swarm.time());
  }
}

// The heightfield: one point per cell, height and vertical velocity (VTK only: PLY has no form).
TEST_F(ExportFieldsTest, RipplesHeightAndVerticalVelocityAreTheModelsState) {
  ripples::Params p;
  p.width = 64;
  p.height = 48;
  ripples::Ripples r(shaders(), p);
  r.touch(0.3f, 0.6f, 0.1f, 0.02f);
  for (int k = 0; k < 5; ++k) r.stepOnce(1.0 / 120.0);
  const std::vector<float> state = r.download();
  Expected e;
  for (std::size_t i = 0; i + 1 < state.size(); i += 2)
    e.add("height", state[i]), e.add("vertical_velocity", state[i + 1]);
  expectBothFormats(ripplesSource(r), e, r.time(), false);
}
