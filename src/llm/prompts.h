// The paper's prompt templates, read from data files (data/prompts/) and
// instantiated with the agent's task context.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "llm/llm_client.h"
#include "util/result.h"

namespace apprentice::llm {

// The slots of the (TASK) line, plus the subtask (not in the prompt, but part
// of what a query is about).
struct TaskContext {
  std::string task;             // "tidy kitchen"
  std::string subtask;          // "clear"
  std::string location;         // where the agent is: "kitchen"
  std::string object;           // object category as perceived: "ceramic-plate"
  std::string object_location;  // with its preposition: "on table"
  // Goal statements already rejected for this object: the goal prompt lists
  // them ("Not: the ketchup is in the cupboard.") before its (RESULT) line,
  // the failure context the paper's future work proposes.
  std::vector<std::string> rejected = {};
};

// The QueryAbout for a query of `kind` in this context (place is the object
// location without its preposition).
QueryAbout about_for(const TaskContext& context, QueryKind kind);

class PromptTemplates {
 public:
  // Reads examples.txt, goal.txt and action.txt from `dir`. Errors: kNotFound
  // or kIo for a missing or unreadable file, kInvalidInput for a template with
  // an unknown {placeholder} or without the ones it needs.
  static Result<PromptTemplates> load(const std::filesystem::path& dir);

  // The goal prompt; it ends with "(RESULT)" so the model writes the goal.
  // With rejected statements in the context, one line "Not: <statement>."
  // per statement goes just before that last line (the statement without
  // its "the goal is that").
  std::string goal_prompt(const TaskContext& context) const;

  // The action prompt for the step after `steps_so_far`; it ends with the
  // next step number and a dot ("Steps:\n1. Open dishwasher\n2.") so the model
  // writes that step. `goal` goes verbatim between (RESULT) and (END RESULT).
  std::string action_prompt(const TaskContext& context, std::string_view goal,
                            std::span<const std::string> steps_so_far) const;

 private:
  PromptTemplates(std::string goal, std::string action)
      : goal_(std::move(goal)), action_(std::move(action)) {}

  std::string goal_;    // with {examples} already filled in
  std::string action_;  // with {examples} already filled in
};

}  // namespace apprentice::llm
