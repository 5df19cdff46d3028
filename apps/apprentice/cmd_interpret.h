// `apprentice interpret`: what a sentence means in a scenario's world.
//
//   apprentice interpret --scenario F [--object ID] [--subtask VERB] "sentence"
//     prints the logical form and its grounding, or the failure and its reason;
//   apprentice interpret --scenario F --corpus FILE.jsonl [--json]
//     grounds the `response` of every line for that line's object and
//     subtask and prints counts by outcome and agreement with `stars_viable`;
//   apprentice interpret --scenario F --asked KIND [--object ID] [--recent ID]
//                        [--choices ID,ID] "reply"
//     reads the sentence as a teacher's reply at that kind of question
//     (language/reply.h): its meaning, or why it cannot be used and
//     replies that would work; exit 1 when unusable or ambiguous.
//
// Outcomes (main() maps them to exit codes): success when the sentence
// grounded (or the corpus report was printed); kGoalNotReached (exit 1)
// when it parsed but did not ground (unknown word, no such object,
// affordance mismatch, unknown predicate); an kInvalidInput or kNotFound
// error (exit 2) for bad options or files, or a sentence the grammar does
// not cover.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "outcome.h"

namespace apprentice::cli {

struct InterpretOptions {
  std::string scenario;                // YAML file; required
  std::optional<std::string> object;   // an id ("mug2") or a category ("mug")
  std::optional<std::string> subtask;  // "clear": a category --object is taken at its place
  std::optional<std::string> sentence; // exactly one of sentence and corpus
  std::optional<std::string> corpus;   // JSON-lines file
  // --asked: read the sentence as a reply to this kind of question
  // (question_kinds(), face/apprentice.h: task, task-step, subtask-end, goal, action, yes-no, which).
  std::optional<std::string> asked;
  std::optional<std::string> recent;   // the place named last (an id)
  std::vector<std::string> choices;    // ids offered at a which-question
  bool json = false;
};

CommandResult run_interpret(const InterpretOptions& options, std::ostream& out);

}  // namespace apprentice::cli
