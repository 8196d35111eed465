// gl::DispatchGate: a recorded section runs when recorded, and on replay runs exactly when the
// arguments buffer holds the recorded group counts (here written from the CPU, as a deciding
// kernel would on the GPU); a replay that issues other dispatches than the recording is refused.
#include "gl/dispatch_gate.h"

#include <gtest/gtest.h>

#include "base/error.h"
#include "gl/buffer.h"
#include "gl/buffer_ops.h"
#include "support/error_of.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::gl;

namespace {
class DispatchGateTest : public test::GlTest {};

// The recorded counts as the arguments (open) or zeros (closed).
void decide(DispatchGate& gate, bool open) {
  std::vector<GLuint> args;
  for (const glm::uvec4& g : gate.recordedGroups().read<glm::uvec4>(gate.dispatches()))
    for (int c = 0; c < 3; ++c) args.push_back(open ? g[c] : 0u);
  gate.arguments().upload(args.data(), args.size() * sizeof(GLuint));
}
}  // namespace

TEST_F(DispatchGateTest, ReplaysRunOnlyWhenTheArgumentsSaySo) {
  const BufferOps ops(shaders());
  Buffer a(4096 * 4), b(1000 * 4);
  DispatchGate gate;
  std::uint32_t value = 1;
  auto section = [&] {  // two fills of different sizes (several groups each)
    ops.fill(a, value);
    ops.fill(b, value + 100);
  };
  gate.record(section);
  ASSERT_EQ(gate.dispatches(), 2u);
  EXPECT_EQ(a.read<std::uint32_t>(4096), std::vector<std::uint32_t>(4096, 1u)) << "recording runs the section";
  EXPECT_EQ(b.read<std::uint32_t>(1000), std::vector<std::uint32_t>(1000, 101u));

  value = 2;
  decide(gate, false);
  gate.replay(section);
  EXPECT_EQ(a.read<std::uint32_t>(4096), std::vector<std::uint32_t>(4096, 1u)) << "closed: nothing ran";
  EXPECT_EQ(b.read<std::uint32_t>(1000), std::vector<std::uint32_t>(1000, 101u));

  value = 3;
  decide(gate, true);
  gate.replay(section);
  EXPECT_EQ(a.read<std::uint32_t>(4096), std::vector<std::uint32_t>(4096, 3u)) << "open: every word written";
  EXPECT_EQ(b.read<std::uint32_t>(1000), std::vector<std::uint32_t>(1000, 103u));

  // Outside a section, dispatches run directly.
  ops.fill(a, 9);
  EXPECT_EQ(a.read<std::uint32_t>(1)[0], 9u);
}

TEST_F(DispatchGateTest, NotingKeepsTheDispatchesWithoutRunningThem) {
  const BufferOps ops(shaders());
  Buffer a(256 * 4);
  ops.fill(a, 5);
  DispatchGate gate;
  gate.note([&] { ops.fill(a, 6); });
  EXPECT_EQ(a.read<std::uint32_t>(256), std::vector<std::uint32_t>(256, 5u));
  decide(gate, true);
  gate.replay([&] { ops.fill(a, 6); });
  EXPECT_EQ(a.read<std::uint32_t>(256), std::vector<std::uint32_t>(256, 6u));
}

TEST_F(DispatchGateTest, AReplayThatDiffersFromTheRecordingIsRefused) {
  const BufferOps ops(shaders());
  Buffer a(4096 * 4), b(64 * 4);
  DispatchGate gate;
  gate.record([&] { ops.fill(a, 1); });
  decide(gate, true);
  EXPECT_NE(test::errorOf([&] { gate.replay([&] { ops.fill(b, 1); }); }).find("differs from the recorded section"),
            std::string::npos);
  EXPECT_NE(test::errorOf([&] {
              gate.replay([&] {
                ops.fill(a, 1);
                ops.fill(a, 2);
              });
            }).find("differs from the recorded section"),
            std::string::npos);
  EXPECT_NE(test::errorOf([&] { gate.replay([] {}); }).find("replayed 0 dispatches, recorded 1"), std::string::npos);
  DispatchGate empty;
  EXPECT_NE(test::errorOf([&] { empty.replay([] {}); }).find("replay before record"), std::string::npos);
  // After a refusal the thread is out of the section again: dispatches run directly.
  ops.fill(b, 4);
  EXPECT_EQ(b.read<std::uint32_t>(1)[0], 4u);
}
