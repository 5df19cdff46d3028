// The readings of "same as X" and of "socks too" / "same again"
// (language/same_as.h): which words name the other thing, and which
// replies are not of these forms at all.
#include <gtest/gtest.h>

#include "language/same_as.h"

namespace apprentice::language {
namespace {

TEST(ReadSameAs, NamesTheOtherThingAndWhatFollows) {
  EXPECT_EQ(read_same_as("same as the soda can").other, "soda can");
  EXPECT_EQ(read_same_as("The same place as the mug.").other, "mug");
  EXPECT_EQ(read_same_as("like the soda cans").other, "soda cans");
  EXPECT_EQ(read_same_as("where the soda can goes").other, "soda can");
  EXPECT_EQ(read_same_as("crayons go with the blocks").other, "blocks");
  EXPECT_EQ(read_same_as("same as the book on the floor").other, "book");
  EXPECT_EQ(read_same_as("same as the hammer please").other, "hammer");
  SameAs with_more = read_same_as("same as the hammer, and shut the drawer afterwards");
  EXPECT_EQ(with_more.other, "hammer");
  EXPECT_EQ(with_more.more, "shut the drawer afterwards");
  EXPECT_EQ(read_same_as("put it in the fridge").other, "");
  // "with the stapler" alone, as people say it (issue 21): where the
  // stapler went. A place said with "with" after it is not one.
  EXPECT_EQ(read_same_as("with the stapler").other, "stapler");
  EXPECT_EQ(read_same_as("ok, put it in with the mugs please").other, "mugs");
  EXPECT_EQ(read_same_as("the shelf with the others").other, "");
}

TEST(ReadSameAgain, NamesTheThingAskedAboutOrNothing) {
  EXPECT_EQ(read_same_again("socks too"), "socks");
  EXPECT_EQ(read_same_again("The sock as well."), "sock");
  EXPECT_EQ(read_same_again("ok, the glass tumbler too please"), "glass tumbler");
  EXPECT_EQ(read_same_again("the socks go there too"), "socks");
  EXPECT_EQ(read_same_again("same for the socks"), "socks");
  EXPECT_EQ(read_same_again("also the socks"), "socks");
  for (const char* bare : {"same again", "Same.", "the same", "ditto", "that too", "it too", "this one too",
                           "same as before", "same for this one", "it goes there too", "and that one too"})
    EXPECT_EQ(read_same_again(bare), "") << bare;
}

TEST(ReadSameAgain, IsNotAnOrdinaryGoalOrAnotherComparison) {
  for (const char* other : {"put it in the top drawer too", "put it in the fridge and close it too",
                            "same as the mug", "the sock goes in the washer", "socks", "too many things here",
                            "put the big red glass tumbler in the sink too"})
    EXPECT_FALSE(read_same_again(other).has_value()) << other;
}

}  // namespace
}  // namespace apprentice::language
