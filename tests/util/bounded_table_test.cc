#include "util/bounded_table.h"

#include <string>

#include <gtest/gtest.h>

namespace apprentice::util {
namespace {

TEST(BoundedTable, KeepsAnswersUpToItsCapacity) {
  BoundedTable<std::string, int> table(3);
  table.remember("a", 1);
  table.remember("b", 2);
  table.remember("c", 3);
  ASSERT_NE(table.find(std::string_view("b")), nullptr);
  EXPECT_EQ(*table.find(std::string_view("b")), 2);
  EXPECT_EQ(table.size(), 3u);
  EXPECT_EQ(table.find(std::string_view("z")), nullptr);
}

TEST(BoundedTable, StartsAgainWhenFullSoThatDistinctKeysCannotGrowIt) {
  BoundedTable<std::string, int> table(3);
  for (int i = 0; i < 1000; ++i) table.remember("k" + std::to_string(i), i);
  EXPECT_LE(table.size(), 3u);
  // The newest answer survives the restart.
  ASSERT_NE(table.find(std::string("k999")), nullptr);
  EXPECT_EQ(*table.find(std::string("k999")), 999);
  EXPECT_EQ(table.find(std::string("k0")), nullptr);
}

TEST(BoundedTable, ReplacesAnAnswerWithoutGrowing) {
  BoundedTable<std::string, int> table(2);
  table.remember("a", 1);
  table.remember("a", 5);
  EXPECT_EQ(table.size(), 1u);
  EXPECT_EQ(*table.find(std::string("a")), 5);
}

}  // namespace
}  // namespace apprentice::util
