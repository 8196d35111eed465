// checkpointDifference: equal checkpoints have none; otherwise one line names each differing
// entry (up to four) with how many of its bytes differ and where the first is.
#include "io/checkpoint_diff.h"

#include <gtest/gtest.h>

using namespace tidepool;

namespace {

io::Checkpoint sample() {
  io::Checkpoint c;
  c.model = "balls";
  c.scene = "cup.json";
  c.params = R"({"engine": {"dt": 0.0004}})";
  c.time = 0.25;
  c.steps = 7;
  c.entries = {{io::EntryKind::Value, "model.count", {1, 0, 0, 0}},
               {io::EntryKind::Buffer, "model.positions", std::vector<std::uint8_t>(64, 3)},
               {io::EntryKind::Text, "model.rng", {'4', '2'}}};
  return c;
}

}  // namespace

TEST(CheckpointDifference, EqualCheckpointsHaveNone) {
  EXPECT_EQ(io::checkpointDifference(sample(), sample()), std::nullopt);
}

TEST(CheckpointDifference, NamesTheEntryTheBytesAndTheFirst) {
  io::Checkpoint b = sample();
  b.entries[1].bytes[17] = 9;
  b.entries[1].bytes[40] = 9;
  EXPECT_EQ(io::checkpointDifference(sample(), b),
            "1 of 4 entries differ: 'model.positions' (2 of 64 bytes, the first at byte 17)");
}

TEST(CheckpointDifference, SizesMissingEntriesParametersAndClocks) {
  io::Checkpoint b = sample();
  b.entries[0].bytes.resize(8);
  b.entries.erase(b.entries.begin() + 2);
  b.entries.push_back({io::EntryKind::Value, "model.extra", {0}});
  b.params = "{}";
  EXPECT_EQ(io::checkpointDifference(sample(), b),
            "4 of 4 entries differ: the parameters, 'model.count' (4 bytes, not 8), 'model.rng' (only in the first), "
            "'model.extra' (only in the second)");
  b = sample();
  b.time = 0.5;
  EXPECT_NE(io::checkpointDifference(sample(), b)->find("the times differ"), std::string::npos);
  b = sample();
  b.steps = 8;
  EXPECT_NE(io::checkpointDifference(sample(), b)->find("the step counts differ"), std::string::npos);
  b = sample();
  b.model = "fluid";
  EXPECT_NE(io::checkpointDifference(sample(), b)->find("the models differ"), std::string::npos);
}
