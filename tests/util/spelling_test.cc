// closest_match: the "did you mean" of the command line and the readers.
#include "util/spelling.h"

#include <gtest/gtest.h>

namespace apprentice {
namespace {

const std::vector<std::string> kCommands{"world", "plan", "export-pddl", "interpret", "experiment",
                                         "teach", "run", "knowledge"};

TEST(ClosestMatch, FindsASlipOfOneOrTwoEdits) {
  EXPECT_EQ(closest_match("tech", kCommands), "teach");
  EXPECT_EQ(closest_match("plna", kCommands), "plan");  // two letters swapped: one edit
  EXPECT_EQ(closest_match("experimnet", kCommands), "experiment");
  EXPECT_EQ(closest_match("KNOWLEDGE", kCommands), "knowledge");
  EXPECT_EQ(closest_match("ketchup", {"milk1", "ketchup1", "ketchup2"}), "ketchup1");
}

TEST(ClosestMatch, SaysNothingWhenNothingIsNear) {
  EXPECT_EQ(closest_match("frobnicate", kCommands), std::nullopt);
  EXPECT_EQ(closest_match("xyz", kCommands), std::nullopt);
  EXPECT_EQ(closest_match("", kCommands), std::nullopt);
  EXPECT_EQ(closest_match("ru", {"run"}), std::nullopt);  // one edit in two letters is too many
  EXPECT_EQ(closest_match("teach", {}), std::nullopt);
}

TEST(ClosestMatch, PrefersTheNearestThenTheFirst) {
  EXPECT_EQ(closest_match("mug", {"mud", "mug1", "mug"}), "mug");
  EXPECT_EQ(closest_match("cup", {"cub", "cut"}), "cub");
}

}  // namespace
}  // namespace apprentice
