// One parameter declaration drives reading (with validation) and writing.
#include <gtest/gtest.h>

#include "base/error.h"
#include "scene/param_json.h"

using namespace tidepool;

namespace {
enum class Method { Euler, Verlet };
constexpr std::array<const char*, 2> kMethodNames = {"euler", "verlet"};

struct P {
  float dt = 0.01f;
  int substeps = 4;
  bool walls = true;
  Method method = Method::Verlet;
  glm::vec3 color{0.1f, 0.2f, 0.3f};
  glm::vec3 gravity{0.0f, -9.81f, 0.0f};
  std::string label = "x";
  float inner = 1.0f;
};

void visit(ParamVisitor& v, P& p) {
  v.real({"dt", "dt", "s"}, p.dt, 1e-5f, 1.0f);
  v.integer({"substeps", "Substeps", ""}, p.substeps, 1, 64);
  v.flag({"walls", "Walls", ""}, p.walls);
  v.choice({"method", "Method", ""}, p.method, kMethodNames);
  v.color({"color", "Colour", ""}, p.color);
  v.vector({"gravity", "Gravity", "m/s^2"}, p.gravity, -100.0f, 100.0f);
  v.text({"label", "Label", ""}, p.label);
  if (v.beginGroup({"group", "Group", ""})) {
    v.real({"inner", "Inner", ""}, p.inner, 0.0f, 2.0f);
    v.endGroup();
  }
}

P read(const std::string& text) {
  P p;
  readParams(
      io::parseJson(text, "t.json"), [&](ParamVisitor& v) { visit(v, p); }, "t.json: params");
  return p;
}

std::string errorOf(const std::string& text) {
  try {
    read(text);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(ParamJson, AbsentKeysKeepDefaultsAndNullMeansDefaults) {
  P p = read("{\"substeps\": 8}");
  EXPECT_EQ(p.substeps, 8);
  EXPECT_FLOAT_EQ(p.dt, 0.01f);
  EXPECT_EQ(read("null").substeps, 4);
}

TEST(ParamJson, WriteThenReadRoundTrips) {
  P p;
  p.dt = 0.002f;
  p.substeps = 3;
  p.walls = false;
  p.method = Method::Euler;
  p.color = {1, 0.5f, 0};
  p.gravity = {0, 0, -1};
  p.label = "hello";
  p.inner = 1.5f;
  const io::Json j = writeParams([&](ParamVisitor& v) { visit(v, p); });
  EXPECT_EQ(j["method"], "euler");
  EXPECT_FLOAT_EQ(j["group"]["inner"].get<float>(), 1.5f);
  P q = read(j.dump());
  EXPECT_FLOAT_EQ(q.dt, p.dt);
  EXPECT_EQ(q.substeps, 3);
  EXPECT_FALSE(q.walls);
  EXPECT_EQ(q.method, Method::Euler);
  EXPECT_EQ(q.color, p.color);
  EXPECT_EQ(q.gravity, p.gravity);
  EXPECT_EQ(q.label, "hello");
  EXPECT_FLOAT_EQ(q.inner, 1.5f);
}

TEST(ParamJson, ValidationMessagesNameTheKeyAndTheProblem) {
  EXPECT_EQ(errorOf("{\"substeps\": 0}"), "t.json: params.substeps = 0 is out of range [1, 64]");
  EXPECT_EQ(errorOf("{\"substeps\": 2.5}"), "t.json: params.substeps: expected a whole number, got 2.5");
  EXPECT_EQ(errorOf("{\"dt\": \"fast\"}"), "t.json: params.dt: expected a number, got \"fast\"");
  EXPECT_EQ(errorOf("{\"walls\": 1}"), "t.json: params.walls: expected true or false, got 1");
  EXPECT_EQ(errorOf("{\"method\": \"rk5\"}"), "t.json: params.method = 'rk5' is not one of: euler, verlet");
  EXPECT_EQ(errorOf("{\"color\": [1, 2]}"), "t.json: params.color: expected an array of 3 numbers, got [1,2]");
  EXPECT_EQ(errorOf("{\"color\": [1, 2, 0]}"), "t.json: params.color[1] = 2 is out of range [0, 1]");
  EXPECT_EQ(errorOf("{\"group\": {\"iner\": 1}}"), "t.json: params.group.iner: unknown key (known here: inner)");
  EXPECT_EQ(errorOf("{\"group\": 3}"), "t.json: params.group: expected an object {...}, got number");
  EXPECT_NE(errorOf("{\"substep\": 3}").find("params.substep: unknown key (known here: dt, substeps, walls"),
            std::string::npos);
  EXPECT_EQ(errorOf("[1]"), "t.json: params: expected an object {...}, got array");
}
