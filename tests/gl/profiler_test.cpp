// GL_TIME_ELAPSED per named pass, harvested without stalls; finish() collects everything.
#include <gtest/gtest.h>

#include "gl/buffer.h"
#include "gl/gpu_profiler.h"
#include "support/gl_test.h"

using namespace tidepool;
using namespace tidepool::gl;

namespace {
class Profiler : public test::GlTest {};
}  // namespace

TEST_F(Profiler, RecordsNamedPassesPerFrame) {
  Program& fill = shaders().program({"selftest/fill.comp"});
  Buffer out(1 << 20);
  out.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  GpuProfiler profiler;
  for (int frame = 0; frame < 5; ++frame) {
    profiler.beginFrame();
    {
      auto s = profiler.scope("fill");
      fill.use();
      fill.set("uCount", uint32_t(1 << 18));
      fill.set("uMul", 1u);
      fill.dispatchThreads(1 << 18);
    }
    {
      auto s = profiler.scope("copy");
      out.copyTo(out, 1 << 19, 0, 1 << 19);
    }
    {
      auto s = profiler.scope("fill");
      fill.dispatchThreads(1 << 10);
    }  // summed with the first
    profiler.endFrame();
  }
  profiler.finish();
  auto frames = profiler.takeCompleted();
  EXPECT_EQ(frames.size() + std::size_t(profiler.dropped()), 5u);
  ASSERT_FALSE(frames.empty());
  ASSERT_EQ(frames.back().passes.size(), 3u);
  EXPECT_EQ(frames.back().passes[0].first, "fill");
  EXPECT_EQ(frames.back().passes[1].first, "copy");
  ASSERT_EQ(profiler.passes().size(), 2u);
  EXPECT_EQ(profiler.passes()[0].name, "fill");
  EXPECT_GT(profiler.passes()[0].ms, 0.0);
  EXPECT_GE(profiler.totalMs(), profiler.passes()[0].ms);
  EXPECT_TRUE(profiler.takeCompleted().empty());
}

// A long run with many passes a frame (25 substeps of 5 passes) that never takes its frames
// keeps only the last few: 4096 of them grew a soak's memory by ~5 KiB a frame
// (docs/RELIABILITY.md, "Long runs").
TEST_F(Profiler, KeepsOnlyTheLastFewFramesUntaken) {
  GpuProfiler profiler;
  for (int frame = 0; frame < 40; ++frame) {
    profiler.beginFrame();
    for (int pass = 0; pass < 125; ++pass) auto s = profiler.scope(pass % 2 ? "odd" : "even");
    profiler.endFrame();
    glFinish();  // every frame's results ready in time: none dropped
  }
  profiler.finish();
  const auto frames = profiler.takeCompleted();
  EXPECT_EQ(profiler.dropped(), 0);
  EXPECT_EQ(frames.size(), 16u);
  ASSERT_FALSE(frames.empty());
  EXPECT_EQ(frames.back().passes.size(), 125u);
  ASSERT_EQ(profiler.passes().size(), 2u) << "the last frame's passes, summed per name";
}

TEST_F(Profiler, NestedScopesAreRefused) {
  GpuProfiler profiler;
  profiler.beginFrame();
  auto outer = profiler.scope("outer");
  EXPECT_THROW((void)profiler.scope("inner"), GlError);
}

TEST_F(Profiler, DisabledProfilerRecordsNothing) {
  GpuProfiler profiler;
  profiler.setEnabled(false);
  profiler.beginFrame();
  { auto s = profiler.scope("x"); }
  profiler.endFrame();
  profiler.finish();
  EXPECT_TRUE(profiler.takeCompleted().empty());
}
