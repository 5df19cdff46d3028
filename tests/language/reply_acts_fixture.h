// The fixture of the read_acts tests (reply_acts_test.cc and
// reply_acts_reasons_test.cc): set 1's bathroom, with look-alike drawers and
// a hamper with a lid (tests/language/fresh/set1/bathroom.yaml).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "fresh_corpus.h"
#include "language/reply.h"
#include "language_fixtures.h"

namespace apprentice::language {

using testing::grounder;
using testing::source_path;

class ReplyActsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string error;
    scenario_ = worlds_.get("bathroom.yaml", error);
    ASSERT_NE(scenario_, nullptr) << error;
  }
  const World& world() const { return scenario_->world; }
  ObjectId id(std::string_view name) const {
    auto found = world().universe->find(name);
    EXPECT_TRUE(found.has_value()) << name;
    return found.value_or(0);
  }
  // A goal question about `object`, after `last` was told to go in `place`.
  ReplyContext goal_question(std::string_view object, std::string_view last = "", std::string_view place = "") const {
    ReplyContext c;
    c.asked = Asked::kGoal;
    c.object = id(object);
    if (!last.empty()) {
      c.last_goal = ReplyContext::LastGoal{
          id(last), Goal({Literal{Fact(world().vocabulary.in, {id(last), id(place)}), true}})};
      c.recent_place = id(place);
    }
    return c;
  }
  std::string acts(const ReplyContext& c, std::string_view text) const {
    ReplyActs read = read_acts(grounder(), world(), c, text);
    std::string out;
    for (const Reply& r : read.acts) out += (out.empty() ? "" : " | ") + format_reply(world(), r);
    return out;
  }
  // The notes of reading `text`: how words were taken ("I took ...").
  std::vector<std::string> notes(const ReplyContext& c, std::string_view text) const {
    return read_acts(grounder(), world(), c, text).notes;
  }
  fresh::Worlds worlds_{source_path("tests/language/fresh/set1")};
  const Scenario* scenario_ = nullptr;
};

}  // namespace apprentice::language
