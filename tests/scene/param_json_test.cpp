// One parameter declaration drives reading (with validation) and writing; lists of groups too.
#include <gtest/gtest.h>

#include "base/error.h"
#include "scene/param_json.h"
#include "support/error_of.h"
#include "support/null_visitor.h"

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
  struct Item {
    float size = 0.5f;
    glm::vec3 at{0.0f};
    float depth = 1.0f;  // in a group of the item
  };
  std::vector<Item> items;
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
  v.list({"items", "Items", ""}, p.items, 3, [](ParamVisitor& v, P::Item& item) {
    v.real({"size", "Size", ""}, item.size, 0.001f, 1.0f);
    v.vector({"at", "At", ""}, item.at, -1.0f, 1.0f);
    if (v.beginGroup({"deep", "Deep", ""})) {
      v.real({"depth", "Depth", ""}, item.depth, 0.0f, 10.0f);
      v.endGroup();
    }
  });
}

P read(const std::string& text) {
  P p;
  readParams(
      io::parseJson(text, "t.json"), [&](ParamVisitor& v) { visit(v, p); }, "t.json: params");
  return p;
}

std::string errorOf(const std::string& text) {
  return test::errorOf([&] { read(text); });
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

TEST(ParamJson, ListsReadEveryItemWithDefaultsAndRoundTrip) {
  EXPECT_TRUE(read("{}").items.empty());
  P p = read(R"({"items": [{"size": 0.25}, {}, {"at": [0, 1, -1], "deep": {"depth": 3}}]})");
  ASSERT_EQ(p.items.size(), 3u);
  EXPECT_FLOAT_EQ(p.items[0].size, 0.25f);
  EXPECT_FLOAT_EQ(p.items[1].size, 0.5f) << "absent keys keep the item's defaults";
  EXPECT_EQ(p.items[2].at, glm::vec3(0, 1, -1));
  EXPECT_FLOAT_EQ(p.items[2].depth, 3.0f);
  EXPECT_TRUE(read(R"({"items": []})").items.empty());
  const io::Json j = writeParams([&](ParamVisitor& v) { visit(v, p); });
  ASSERT_TRUE(j["items"].is_array());
  EXPECT_FLOAT_EQ(j["items"][2]["deep"]["depth"].get<float>(), 3.0f);
  EXPECT_FLOAT_EQ(j["group"]["inner"].get<float>(), 1.0f) << "groups after a list still land in the right place";
  const P q = read(j.dump());
  ASSERT_EQ(q.items.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_FLOAT_EQ(q.items[i].size, p.items[i].size);
    EXPECT_EQ(q.items[i].at, p.items[i].at);
    EXPECT_FLOAT_EQ(q.items[i].depth, p.items[i].depth);
  }
}

TEST(ParamJson, ListErrorsNameTheItemByIndex) {
  EXPECT_EQ(errorOf(R"({"items": [{}, {}, {"size": 5}]})"),
            "t.json: params.items[2].size = 5 is out of range [0.001, 1]");
  EXPECT_EQ(errorOf(R"({"items": [{"at": [0, 2, 0]}]})"), "t.json: params.items[0].at[1] = 2 is out of range [-1, 1]");
  EXPECT_EQ(errorOf(R"({"items": [{}, {"deep": {"depth": -1}}]})"),
            "t.json: params.items[1].deep.depth = -1 is out of range [0, 10]");
  EXPECT_EQ(errorOf(R"({"items": [{}, {"sise": 1}]})"),
            "t.json: params.items[1].sise: unknown key (known here: size, at, deep)");
  EXPECT_EQ(errorOf(R"({"items": [{}, 3]})"), "t.json: params.items[1]: expected an object {...}, got 3");
  EXPECT_EQ(errorOf(R"({"items": {"size": 1}})"), "t.json: params.items: expected an array [{...}, ...], got object");
  EXPECT_EQ(errorOf(R"({"items": [{}, {}, {}, {}]})"), "t.json: params.items: 4 items, at most 3");
}

namespace {
// A visitor like the editor's: adds one item, removes another.
class AddAndRemove final : public test::NullVisitor {
 public:
  std::size_t remove = kNoItem;
  std::vector<std::string> names;
  bool beginList(const ParamInfo&, std::size_t& size, std::size_t maxSize) override {
    if (size < maxSize) ++size;
    return true;
  }
  bool beginItem(std::size_t, const std::string& name) override {
    names.push_back(name);
    return true;
  }
  std::size_t endList() override { return remove; }
};
}  // namespace

TEST(ParamJson, ListVisitorsMayAddAndRemoveItems) {
  P p = read(R"({"items": [{"size": 0.1}, {"size": 0.2}]})");
  AddAndRemove edit;
  edit.remove = 0;
  visit(edit, p);
  ASSERT_EQ(p.items.size(), 2u);
  EXPECT_FLOAT_EQ(p.items[0].size, 0.2f);
  EXPECT_FLOAT_EQ(p.items[1].size, 0.5f) << "the added item has the defaults";
  EXPECT_EQ(edit.names, (std::vector<std::string>{"0", "1", "2"}));
  edit.remove = ParamVisitor::kNoItem;
  visit(edit, p);
  EXPECT_EQ(p.items.size(), 3u);
  visit(edit, p);
  EXPECT_EQ(p.items.size(), 3u) << "at most 3";
}
