// Shared helpers for the instructor tests: shipped scenarios, objects by
// name, and an instructor that replies from a list.
#pragma once

#include <deque>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "instructor/instructor.h"
#include "world/scenario.h"

namespace apprentice::testing {

inline std::filesystem::path source_path(std::string_view relative) {
  return std::filesystem::path(APPRENTICE_SOURCE_DIR) / relative;
}

inline std::filesystem::path shared_path(std::string_view relative) {
  return std::filesystem::path(APPRENTICE_SHARED_DIR) / relative;
}

inline Scenario load_or_die(const std::filesystem::path& path) {
  auto scenario = load_scenario(path);
  if (!scenario) {
    ADD_FAILURE() << scenario.error().describe();
    std::abort();
  }
  return std::move(*scenario);
}

inline ObjectId object(const World& world, std::string_view id) {
  auto found = world.universe->find(id);
  EXPECT_TRUE(found.has_value()) << "no object " << id;
  return found.value_or(0);
}

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
