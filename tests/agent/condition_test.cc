// Conditions are named as in the paper's Table 3 and parsed into the
// knowledge sources the agent may use.
#include "agent/condition.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace apprentice {
namespace {

using ::testing::HasSubstr;

struct Expected {
  const char* name;
  bool instruction;
  int search_depth;
  bool llm;
};

class ParseCondition : public ::testing::TestWithParam<Expected> {};

TEST_P(ParseCondition, ReadsTheSources) {
  const Expected& e = GetParam();
  auto condition = parse_condition(e.name);
  ASSERT_TRUE(condition.has_value()) << condition.error().describe();
  EXPECT_EQ(condition->name, e.name);
  EXPECT_EQ(condition->instruction, e.instruction);
  EXPECT_EQ(condition->search_depth, e.search_depth);
  EXPECT_EQ(condition->llm, e.llm);
}

INSTANTIATE_TEST_SUITE_P(PaperAndOthers, ParseCondition,
                         ::testing::Values(Expected{"instruction", true, 0, false},
                                           Expected{"inst", true, 0, false},
                                           Expected{"inst+search4", true, 4, false},
                                           Expected{"search4+llm", false, 4, true},
                                           Expected{"inst+llm", true, 0, true},
                                           Expected{"inst+search2+llm", true, 2, true},
                                           Expected{"inst+search4+llm", true, 4, true},
                                           Expected{"instruction+search1", true, 1, false},
                                           Expected{"llm", false, 0, true},
                                           Expected{"llm+search16+inst", true, 16, true}));

TEST(ParseCondition, ThePapersSixConditionsParseInTableOrder) {
  std::vector<std::string> names = paper_condition_names();
  EXPECT_THAT(names, ::testing::ElementsAre("instruction", "inst+search4", "search4+llm", "inst+llm",
                                            "inst+search2+llm", "inst+search4+llm"));
  for (const std::string& name : names) EXPECT_TRUE(parse_condition(name).has_value()) << name;
}

TEST(ParseCondition, SearchWithoutADepthIsUnboundedSearch) {
  auto condition = parse_condition("inst+search");
  ASSERT_TRUE(condition.has_value()) << condition.error().describe();
  EXPECT_TRUE(condition->instruction);
  EXPECT_TRUE(condition->unbounded_search);
  EXPECT_EQ(condition->search_depth, 0);
  EXPECT_FALSE(parse_condition("inst+search4")->unbounded_search);
  EXPECT_TRUE(parse_condition("search+llm")->unbounded_search);
}

struct Bad {
  const char* name;
  const char* message;  // a part of the error message
};

class ParseConditionError : public ::testing::TestWithParam<Bad> {};

TEST_P(ParseConditionError, IsRejectedWithAReason) {
  auto condition = parse_condition(GetParam().name);
  ASSERT_FALSE(condition.has_value()) << GetParam().name << " was accepted";
  EXPECT_EQ(condition.error().code, ErrorCode::kInvalidInput);
  EXPECT_THAT(condition.error().message, HasSubstr(GetParam().message));
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, ParseConditionError,
    ::testing::Values(Bad{"", "empty condition"},
                      Bad{"search4", "nothing can supply goals"},       // no source of goals
                      Bad{"search0+inst", "depth from 1 to 16"},
                      Bad{"search17+inst", "depth from 1 to 16"},
                      Bad{"searchx+inst", "depth from 1 to 16"},
                      Bad{"search4x+inst", "depth from 1 to 16"},
                      Bad{"search-1+inst", "depth from 1 to 16"},
                      Bad{"inst+gpt", "not 'gpt'"},
                      Bad{"Instruction", "not 'Instruction'"},
                      Bad{"inst++llm", "not ''"},
                      Bad{"+inst", "not ''"},
                      Bad{"inst+", "not ''"},
                      Bad{"inst llm", "not 'inst llm'"}));

}  // namespace
}  // namespace apprentice
