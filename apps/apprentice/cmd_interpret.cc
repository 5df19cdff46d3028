#include "cmd_interpret.h"

#include <ostream>

#include "face/apprentice.h"

namespace apprentice::cli {

CommandResult run_interpret(const InterpretOptions& options, std::ostream& out) {
  if (options.sentence.has_value() == options.corpus.has_value())
    return make_error(ErrorCode::kInvalidInput, "interpret takes either a sentence or --corpus FILE");
  auto scenario = load_world(options.scenario);
  if (!scenario) return tl::unexpected(scenario.error());
  if (options.corpus) {
    auto report = interpret_corpus(*scenario, *options.corpus, options.json);
    if (!report) return tl::unexpected(report.error());
    out << *report;
    return Outcome::kSuccess;
  }
  if (options.asked) {
    AskedQuestion asked{*options.asked, options.object, options.subtask, options.recent, options.choices};
    auto reading = interpret_reply(*scenario, *options.sentence, asked);
    if (!reading) return tl::unexpected(reading.error());
    out << (options.json ? reading->json : reading->text);
    return reading->usable ? Outcome::kSuccess : Outcome::kGoalNotReached;
  }
  auto reading = interpret_sentence(*scenario, *options.sentence, options.object, options.subtask);
  if (!reading) return tl::unexpected(reading.error());
  out << (options.json ? reading->json : reading->text);
  if (reading->outside_grammar)
    return make_error(ErrorCode::kInvalidInput, "the sentence is outside the grammar: " + reading->detail);
  return reading->grounded ? Outcome::kSuccess : Outcome::kGoalNotReached;
}

}  // namespace apprentice::cli
