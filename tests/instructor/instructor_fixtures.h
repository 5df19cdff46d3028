// Helpers for the instructor tests: an instructor that replies from a list.
// Paths, scenarios and objects by name come from tests/common.
#pragma once

#include <deque>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "common/paths.h"
#include "common/world_helpers.h"
#include "instructor/instructor.h"

namespace apprentice::testing {

// Replies with the given lines in order, then kCancelled; keeps what it
// was asked and told.
class ScriptedInstructor final : public Instructor {
 public:
  explicit ScriptedInstructor(std::vector<std::string> replies) : replies_(replies.begin(), replies.end()) {}
  Result<std::string> answer(const Question& question, const World&) override {
    questions.push_back(question);
    if (replies_.empty()) return make_error(ErrorCode::kCancelled, "no more replies");
    std::string reply = replies_.front();
    replies_.pop_front();
    return reply;
  }
  void hear(std::string_view statement) override { heard.emplace_back(statement); }

  std::vector<Question> questions;
  std::vector<std::string> heard;

 private:
  std::deque<std::string> replies_;
};

}  // namespace apprentice::testing
