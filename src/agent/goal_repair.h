// Analysis and repair of goals an LLM proposes, before the agent uses one
// or offers one to the instructor, in the spirit of the STARS follow-up of
// Kirk et al. (an agent that analyses LLM responses and repairs them).
//
// For each retrieved goal statement, in this order:
//  1. ground it (the language module's grounder, through Understanding);
//  2. drop (`drop`): a clause that can never hold here (an affordance the
//     world lacks: closing a lidless bin) or that uses a predicate the
//     domain lacks ("the dishwasher is turned on") is left out; the rest is
//     kept if it still gives the object a destination. Any other failure
//     (a phrase that names nothing here, a sentence the grammar cannot read)
//     makes the statement unusable;
//  3. complete closings (`close`): putting the object into a receptacle with
//     a door adds "the receptacle is closed" when the goals learned for that
//     kind of receptacle end closed, or, with none learned for it, under the
//     default norm "close what you opened" (it is closed now, so the agent
//     will have opened it); goals learned for it that leave it open mean it
//     stays open;
//  4. check (`check`): the goal must give the object a destination other
//     than where it is, must not hold already, and search must reach it
//     (to `check_depth` actions);
//  5. choose (`choose`): usable goals are merged when they are the same goal
//     after repair, and ordered by their agreement: the summed probability
//     of the statements that repair to the same destination (a statement
//     whose probability the backend did not give counts 1); ties go to the
//     more probable statement, then the earlier one. Without this step they
//     keep their retrieval order, for Algorithm 5 to sort by mean
//     log-probability.
// Each step can be turned off (GoalRepairOptions) to measure what it adds.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "agent/understanding.h"
#include "knowledge/goal_memory.h"
#include "llm/retrieval.h"
#include "util/result.h"
#include "world/goal.h"
#include "world/world.h"

namespace apprentice {

struct GoalRepairOptions {
  bool drop = true;      // leave out clauses that can never hold
  bool close = true;     // complete closings
  bool check = true;     // destination, not already holding, reachable by search
  bool choose = true;    // merge and order by agreement; unattended: the best usable one
  bool reprompt = true;  // re-prompt with the rejected answers (the agent does it)
  int check_depth = 8;   // open, pick up, put, close, and putting down what is held
  std::uint64_t check_max_nodes = 20'000;  // a reachable kitchen goal takes about a hundred
  // With `choose` and an instructor, only the best goal is offered, and only
  // if at least this share of the usable statements (by weight) agree on
  // its destination: by default all of them. The instructor is asked to
  // describe the goal rather than to turn down goals the model itself is
  // not consistent about.
  double offer_share = 1.0;

  // Everything off: the paper's agent, which grounds a response as it is.
  static GoalRepairOptions none();
};

// Parses "all", "none", or a comma-separated list of the steps drop, close,
// check, choose, reprompt; a step with a leading '-' is removed from all
// ("-choose": every step but choose). kInvalidInput names what is wrong.
Result<GoalRepairOptions> parse_goal_repair(std::string_view text);
// The inverse, for logs and tables: "all", "none" or the list.
std::string format_goal_repair(const GoalRepairOptions& options);

// What the analysis made of one retrieved statement.
struct AnalysedGoal {
  llm::Candidate candidate;
  int position = 0;                  // in retrieval order
  std::optional<Goal> goal;          // set when usable
  std::vector<std::string> dropped;  // the clauses left out, each with why
  std::vector<ObjectId> closings;    // receptacles whose closing was added
  std::vector<bool> closing_by_norm; // for each: by the default norm, not from learned goals
  MeaningFailure failure_kind = MeaningFailure::kNone;  // when unusable
  std::string failure;               // a sentence the agent can say
  double weight = 1.0;               // exp(mean log-probability), or 1 when not given
  double score = 0.0;                // what the choice orders by
  double share = 0.0;                // score over the weight of the usable statements
  std::vector<int> merged;           // positions of other statements that repaired to this goal

  bool repaired() const { return !dropped.empty() || !closings.empty(); }
};

struct GoalAnalysis {
  // With `choose`: the usable goals, best first and without repeats, then
  // the unusable statements in retrieval order. Without: every statement in
  // retrieval order.
  std::vector<AnalysedGoal> goals;
  std::uint64_t search_nodes = 0;  // spent checking reachability

  int usable() const;
  // The analysed goal a candidate (by its text) became, if any.
  const AnalysedGoal* find(const llm::Candidate& candidate) const;
  // The candidates in the order above: what finalize_choice is given.
  std::vector<llm::Candidate> ordered_candidates() const;
};

// Analyses the retrieved `candidates` (in retrieval order) for `object` in
// `world`, with the goals learned so far for the closing norm.
GoalAnalysis analyse_goals(Understanding& understanding, const World& world, ObjectId object,
                           const std::vector<llm::Candidate>& candidates, const GoalMemory& learned,
                           const GoalRepairOptions& options);

// "Close what you opened", for any goal (an LLM's, after repair, or a
// teacher's): the receptacles with a door that `goal` puts `object` into,
// closed now, of which the goal says neither closed nor open ("leave it
// open" says open), that should end closed: as the goals learned for that
// kind of receptacle do, or, with none learned for it, by the norm.
struct ClosingToAdd {
  ObjectId place = 0;
  bool by_norm = false;  // not from goals learned for it
};
// A place whose door_key is in `left_open` (the teacher wants it left
// open) is never closed so.
std::vector<ClosingToAdd> closings_to_complete(const World& world, const Goal& goal, ObjectId object,
                                               const GoalMemory& learned, const std::set<std::string>& left_open = {});
// How a place is kept among the doors the teacher wants left open
// (Curriculum::doors_left_open): its category, with the properties that
// tell it apart where the world has several ("top drawer").
std::string door_key(const World& world, ObjectId place);
// "leave the top drawer open from now on": the goals `learned` that close
// `place` (a goal learned for its category where there was one such place,
// or for it by its properties), without that closing, each one's
// provenance saying why, with the teacher's words `said`. What the session
// learns again in their place.
std::vector<GoalKnowledge> goals_leaving_open(const World& world, const GoalMemory& learned, ObjectId place,
                                              const std::string& said);
// "this one stays closed": the goals `learned` that put things in `place`
// and do not close it after, with that closing (and without a wish to
// leave it open), each one's provenance saying why. What the session
// learns again in their place.
std::vector<GoalKnowledge> goals_closing(const World& world, const GoalMemory& learned, ObjectId place,
                                         const std::string& said);
// The places `goal` puts `object` in or on (its positive on/in literals).
std::vector<ObjectId> destinations(const World& world, const Goal& goal, ObjectId object);
// `goal` with `closings` added.
Goal with_closings(const World& world, const Goal& goal, const std::vector<ClosingToAdd>& closings);

// A sentence for the logs and the goal's provenance: what was repaired, e.g.
// "left out 'the recycling bin is closed' (The recycling bin has no door to
// close.); added that the fridge is closed (close what you opened)". Empty
// when nothing was.
std::string describe_repairs(const World& world, const AnalysedGoal& goal);

}  // namespace apprentice
