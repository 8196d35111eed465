// Frame pacing on a real context (llvmpipe): however far the CPU runs ahead, no more than
// maxInFlight frames are ever fenced and pending, and a frame that waited finds its slot's
// oldest fence signalled.
#include <gtest/gtest.h>

#include <vector>

#include "gl/buffer.h"
#include "gl/frame_pacer.h"
#include "support/gl_test.h"

using namespace tidepool;

namespace {
class FramePacer : public test::GlTest {};

// Some GPU work for a "frame": clears and copies of a buffer of a few MB.
void frameWork(gl::Buffer& a, gl::Buffer& b) {
  glBindBuffer(GL_COPY_READ_BUFFER, a.id());
  glBindBuffer(GL_COPY_WRITE_BUFFER, b.id());
  for (int i = 0; i < 4; ++i) glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, a.size());
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
}
}  // namespace

TEST_F(FramePacer, NeverMoreThanMaxFramesInFlight) {
  const std::vector<float> data(1 << 20, 1.0f);
  gl::Buffer a{std::span<const float>(data)}, b{std::span<const float>(data)};
  for (int max : {1, 2, 3}) {
    gl::FramePacer pacer(max);
    EXPECT_EQ(pacer.maxInFlight(), max);
    for (int frame = 0; frame < 40; ++frame) {
      pacer.waitForSlot();
      EXPECT_LT(pacer.inFlight(), max) << "frame " << frame << ": a slot is free before the frame";
      frameWork(a, b);
      pacer.frameSubmitted();
      EXPECT_LE(pacer.inFlight(), max) << "frame " << frame;
      EXPECT_GE(pacer.inFlight(), 1) << "the frame just submitted is pending or done";
    }
    glFinish();
    pacer.waitForSlot();  // all done: everything retires
    EXPECT_EQ(pacer.inFlight(), 0);
  }
}

TEST_F(FramePacer, ACallerThatSkipsTheWaitStaysBounded) {
  const std::vector<float> data(1 << 18, 2.0f);
  gl::Buffer a{std::span<const float>(data)}, b{std::span<const float>(data)};
  gl::FramePacer pacer(2);
  for (int frame = 0; frame < 20; ++frame) {
    frameWork(a, b);
    pacer.frameSubmitted();
    EXPECT_LE(pacer.inFlight(), 2);
  }
  EXPECT_EQ(gl::FramePacer(0).maxInFlight(), 1) << "clamped";
  EXPECT_EQ(gl::FramePacer(100).maxInFlight(), 8);
}
