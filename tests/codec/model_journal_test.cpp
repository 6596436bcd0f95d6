// ModelJournal: a frame written with a journal and then undone leaves the
// adaptive models as they were, and the same frame written again codes the
// same bytes.
#include "model_journal.hpp"

#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "coding_state.hpp"
#include "frame_writer.hpp"

namespace fw::codec {
namespace {

bool same_models(const FrameModels& a, const FrameModels& b) {
  // Plain aggregates of small integers: their bytes say whether they are equal.
  return std::memcmp(&a, &b, sizeof(FrameModels)) == 0;
}

FrameDecision moving_decision(int step) {
  FrameDecision d;
  d.level = 3;
  for (std::size_t c = 0; c < kChannelCount; c += 3) {
    d.update[c] = true;
    d.target[c] = (step * 7 + static_cast<int>(c)) % 40 - 20;
    d.velocity[c] = (step % 5 - 2) * kVelocityUnitSubSteps;
  }
  return d;
}

TEST(ModelJournal, UndoPutsTheModelsOfAPredictedFrameBack) {
  StreamOptions options;
  CodingState state(options.max_extrapolation_ticks);
  std::vector<std::uint8_t> bytes;
  FrameDecision key = moving_decision(0);
  key.type = FrameType::key;
  write_frame(state, options, 0, key, bytes);
  for (int step = 1; step < 20; ++step) write_frame(state, options, 0, moving_decision(step), bytes);

  const FrameModels before = state.models;
  ModelJournal journal;
  std::vector<std::uint8_t> first, again;
  CodingState trial = state;
  write_frame(trial, options, 0, moving_decision(20), first, &journal);
  EXPECT_FALSE(journal.empty());
  EXPECT_FALSE(same_models(trial.models, before)) << "the frame taught the models something";
  journal.undo();
  trial.models.updated_last = before.updated_last;
  trial.models.group_updated_last = before.group_updated_last;
  EXPECT_TRUE(journal.empty());
  EXPECT_TRUE(same_models(trial.models, before));
  trial.reconstruction = state.reconstruction;
  trial.level = state.level;
  write_frame(trial, options, 0, moving_decision(20), again);
  EXPECT_EQ(first, again);
}

}  // namespace
}  // namespace fw::codec
