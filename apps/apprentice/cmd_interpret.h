// `apprentice interpret`: what a sentence means in a scenario's world.
//
//   apprentice interpret --scenario F [--object ID] [--subtask VERB] "sentence"
//     prints the logical form and its grounding, or the failure and its reason;
//   apprentice interpret --scenario F --corpus FILE.jsonl [--json]
//     grounds the `response` of every line for that line's object and
//     subtask and prints counts by outcome and agreement with `stars_viable`.
//
// Exit codes: 0 the sentence grounded (or the corpus report was printed);
// 1 it parsed but did not ground (unknown word, no such object, affordance
// mismatch, unknown predicate); 2 bad input: options, files, or a sentence
// the grammar does not cover.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

namespace apprentice::cli {

struct InterpretOptions {
  std::string scenario;                // YAML file; required
  std::optional<std::string> object;   // an id ("mug2") or a category ("mug")
  std::optional<std::string> subtask;  // "clear": a category --object is taken at its place
  std::optional<std::string> sentence; // exactly one of sentence and corpus
  std::optional<std::string> corpus;   // JSON-lines file
  bool json = false;
};

int run_interpret(const InterpretOptions& options, std::ostream& out, std::ostream& err);

}  // namespace apprentice::cli
