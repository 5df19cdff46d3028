#include "agent/goal_repair.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "language/generation.h"
#include "language/narration.h"
#include "search/iterative_deepening.h"
#include "util/text.h"

namespace apprentice {

GoalRepairOptions GoalRepairOptions::none() {
  GoalRepairOptions options;
  options.drop = options.close = options.check = options.choose = options.reprompt = false;
  return options;
}

namespace {

struct Step {
  const char* name;
  bool GoalRepairOptions::*flag;
};
constexpr Step kSteps[] = {{"drop", &GoalRepairOptions::drop},
                           {"close", &GoalRepairOptions::close},
                           {"check", &GoalRepairOptions::check},
                           {"choose", &GoalRepairOptions::choose},
                           {"reprompt", &GoalRepairOptions::reprompt}};

}  // namespace

Result<GoalRepairOptions> parse_goal_repair(std::string_view text) {
  const std::string spec = to_lower(trim(text));
  if (spec == "all") return GoalRepairOptions{};
  if (spec == "none") return GoalRepairOptions::none();
  std::vector<std::string> items;
  for (std::size_t start = 0; start <= spec.size();) {
    std::size_t comma = spec.find(',', start);
    if (comma == std::string::npos) comma = spec.size();
    std::string_view word = trim(std::string_view(spec).substr(start, comma - start));
    if (!word.empty()) items.emplace_back(word);
    start = comma + 1;
  }
  if (items.empty()) return make_error(ErrorCode::kInvalidInput, "--goal-repair: expected all, none or steps");
  // All removals ("-choose") start from every step; a plain list from none.
  const bool removing = items.front().front() == '-';
  GoalRepairOptions options = removing ? GoalRepairOptions{} : GoalRepairOptions::none();
  for (const std::string& item : items) {
    const bool remove = item.front() == '-';
    if (remove != removing)
      return make_error(ErrorCode::kInvalidInput,
                        "--goal-repair: either list the steps to use or the steps to leave out (with '-'), not both");
    const std::string name = remove ? item.substr(1) : item;
    const Step* step = std::find_if(std::begin(kSteps), std::end(kSteps), [&](const Step& s) { return name == s.name; });
    if (step == std::end(kSteps))
      return make_error(ErrorCode::kInvalidInput, "--goal-repair: '" + name +
                                                      "' is not a step (drop, close, check, choose, reprompt; or all, none)");
    options.*(step->flag) = !remove;
  }
  return options;
}

std::string format_goal_repair(const GoalRepairOptions& options) {
  std::string on;
  int count = 0;
  for (const Step& step : kSteps) {
    if (!(options.*(step.flag))) continue;
    on += (on.empty() ? "" : ",") + std::string(step.name);
    ++count;
  }
  if (count == static_cast<int>(std::size(kSteps))) return "all";
  return count == 0 ? "none" : on;
}

int GoalAnalysis::usable() const {
  return static_cast<int>(std::count_if(goals.begin(), goals.end(), [](const AnalysedGoal& g) { return g.goal; }));
}

const AnalysedGoal* GoalAnalysis::find(const llm::Candidate& candidate) const {
  for (const AnalysedGoal& goal : goals)
    if (goal.candidate.text == candidate.text) return &goal;
  return nullptr;
}

std::vector<llm::Candidate> GoalAnalysis::ordered_candidates() const {
  std::vector<llm::Candidate> out;
  for (const AnalysedGoal& goal : goals) out.push_back(goal.candidate);
  return out;
}

namespace {

// "the recycling bin is closed", "the dishwasher is turned on".
std::string clause_text(const language::Conjunct& conjunct) {
  auto noun = [](const language::NounPhrase& phrase) {
    return (phrase.article.empty() ? std::string() : phrase.article + " ") + phrase.text();
  };
  if (const auto* placement = std::get_if<language::Placement>(&conjunct))
    return noun(placement->thing) + " is " + std::string(language::to_string(placement->relation)) + " " +
           noun(placement->place);
  const auto& property = std::get<language::PropertyStatement>(conjunct);
  std::string words = property.property == language::Property::kClosed ? "closed"
                      : property.property == language::Property::kOpen ? "open"
                                                                         : join(property.words, " ");
  return noun(property.thing) + " is " + words;
}

// Failures of a clause that no repair of wording could fix: the world
// cannot make it true (an affordance it lacks) or the domain has no
// predicate for it. These clauses can be left out.
bool can_never_hold(MeaningFailure failure_kind) {
  return failure_kind == MeaningFailure::kAffordanceMismatch || failure_kind == MeaningFailure::kUnknownPredicate;
}

// Whether a goal's argument stands for `place`: its category, with every
// property that told it apart where it was learned (the top drawer's goal
// is not the bottom drawer's; a drawer's learned where there was one is
// every drawer's).
bool argument_fits(const World& world, const GoalTemplateArgument& argument, ObjectId place) {
  const ObjectInfo& info = world.universe->info(place);
  if (argument.object_of_interest || argument.category != info.category) return false;
  return std::all_of(argument.properties.begin(), argument.properties.end(), [&](const std::string& p) {
    return std::find(info.properties.begin(), info.properties.end(), p) != info.properties.end();
  });
}

// Whether goals learned so far for `place` end closed: true if one does,
// false if some put things into it and none closes it; with none about it,
// true if one closes a look-alike (the middle drawer's goals close the top
// drawer too), else nothing. A goal that says to leave a place open ("the
// umbrella goes in the closet, leave it open so it can dry", "the top
// drawer should stay open") is that place's own exception, and says
// nothing of others.
std::optional<bool> learned_closing(const World& world, const GoalMemory& learned, ObjectId place) {
  const std::string& in = world.domain->predicates[world.vocabulary.in].name;
  const std::string& closed = world.domain->predicates[world.vocabulary.closed].name;
  const std::string& category = world.universe->info(place).category;
  std::optional<bool> verdict;
  bool a_look_alike_closes = false;
  for (const GoalKnowledge& knowledge : learned.all()) {
    bool into = false, closes = false, left_open = false;
    for (const GoalTemplateLiteral& literal : knowledge.literals) {
      const bool its_door = literal.predicate == closed && literal.arguments.size() == 1 &&
                            argument_fits(world, literal.arguments[0], place);
      a_look_alike_closes = a_look_alike_closes || (literal.positive && literal.predicate == closed &&
                                                    literal.arguments.size() == 1 &&
                                                    literal.arguments[0].category == category);
      if (!literal.positive) {
        left_open = left_open || its_door;
        continue;
      }
      if (literal.predicate == in && literal.arguments.size() == 2 && argument_fits(world, literal.arguments[1], place))
        into = true;
      closes = closes || its_door;
    }
    if (closes) return true;
    if (into && !left_open) verdict = false;
  }
  if (!verdict && a_look_alike_closes) return true;
  return verdict;
}

}  // namespace

std::vector<ClosingToAdd> closings_to_complete(const World& world, const Goal& goal, ObjectId object,
                                               const GoalMemory& learned, const std::set<std::string>& left_open) {
  const Vocabulary& v = world.vocabulary;
  std::vector<ClosingToAdd> out;
  for (ObjectId place : destinations(world, goal, object)) {
    if (!world.state.holds(Fact(v.openable, {place})) || left_open.count(door_key(world, place))) continue;
    const Fact closed(v.closed, {place});
    // Closed or open, as said ("leave it open": not closed).
    const bool said = std::any_of(goal.literals.begin(), goal.literals.end(), [&](const Literal& l) { return l.fact == closed; });
    if (said) continue;
    std::optional<bool> learned_verdict = learned_closing(world, learned, place);
    // Closed now: the agent will have opened it.
    const bool close = learned_verdict ? *learned_verdict : world.state.holds(closed);
    if (close) out.push_back(ClosingToAdd{place, !learned_verdict.has_value()});
  }
  return out;
}

std::vector<ObjectId> destinations(const World& world, const Goal& goal, ObjectId object) {
  const Vocabulary& v = world.vocabulary;
  std::vector<ObjectId> out;
  for (const Literal& literal : goal.literals)
    if (literal.positive && (literal.fact.predicate == v.on || literal.fact.predicate == v.in) &&
        literal.fact.arity == 2 && literal.fact.args[0] == object)
      out.push_back(literal.fact.args[1]);
  return out;
}

Goal with_closings(const World& world, const Goal& goal, const std::vector<ClosingToAdd>& closings) {
  std::vector<Literal> literals = goal.literals;
  for (const ClosingToAdd& closing : closings) literals.push_back(Literal{Fact(world.vocabulary.closed, {closing.place}), true});
  return Goal(std::move(literals));
}

namespace {

class Analyser {
 public:
  Analyser(Understanding& understanding, const World& world, ObjectId object, const GoalMemory& learned,
           const GoalRepairOptions& options)
      : understanding_(understanding), world_(world), object_(object), learned_(learned), options_(options) {}

  AnalysedGoal analyse(const llm::Candidate& candidate, int position) {
    AnalysedGoal out;
    out.candidate = candidate;
    out.position = position;
    if (candidate.mean_logprob) out.weight = std::exp(*candidate.mean_logprob);
    if (!ground(out)) return out;
    if (options_.close) complete_closings(out);
    if (options_.check) check(out);
    return out;
  }

  std::uint64_t search_nodes() const { return search_nodes_; }

 private:
  void fail(AnalysedGoal& out, MeaningFailure kind, std::string why) {
    out.goal.reset();
    out.failure_kind = kind;
    out.failure = std::move(why);
  }

  // Steps 1 and 2. False when the statement is unusable.
  bool ground(AnalysedGoal& out) {
    GoalMeaning whole = understanding_.goal(world_, out.candidate.text, object_);
    if (whole.goal) {
      out.goal = std::move(whole.goal);
      return true;
    }
    fail(out, whole.failure_kind, whole.failure);
    if (!options_.drop) return false;
    auto form = understanding_.parse(out.candidate.text);
    if (!form) return false;
    const auto* description = std::get_if<language::GoalDescription>(&*form);
    if (description == nullptr) return false;
    std::vector<Literal> kept;
    std::vector<std::string> dropped;
    for (const language::Conjunct& conjunct : description->conjuncts) {
      language::GoalDescription one{description->category, {conjunct}};
      GoalMeaning clause = understanding_.goal(world_, one, object_);
      if (clause.goal) {
        kept.insert(kept.end(), clause.goal->literals.begin(), clause.goal->literals.end());
      } else if (can_never_hold(clause.failure_kind)) {
        dropped.push_back("'" + clause_text(conjunct) + "' (" + clause.failure + ")");
      } else {
        fail(out, clause.failure_kind, clause.failure);
        return false;
      }
    }
    Goal rest(std::move(kept));
    if (rest.empty() || destinations(world_, rest, object_).empty()) {
      fail(out, MeaningFailure::kNoDestination,
           "Without what cannot hold, " + apprentice::quoted(out.candidate.text) + " says nowhere to put the " +
               world_.universe->info(object_).category + ".");
      return false;
    }
    out.goal = std::move(rest);
    out.dropped = std::move(dropped);
    out.failure_kind = MeaningFailure::kNone;
    out.failure.clear();
    return true;
  }

  // Step 3.
  void complete_closings(AnalysedGoal& out) {
    const std::vector<ClosingToAdd> closings = closings_to_complete(world_, *out.goal, object_, learned_);
    if (closings.empty()) return;
    out.goal = with_closings(world_, *out.goal, closings);
    for (const ClosingToAdd& closing : closings) {
      out.closings.push_back(closing.place);
      out.closing_by_norm.push_back(closing.by_norm);
    }
  }

  // Step 4.
  void check(AnalysedGoal& out) {
    std::vector<ObjectId> places = destinations(world_, *out.goal, object_);
    const std::optional<ObjectId> here = language::place_of(world_, object_);
    const std::string noun = "the " + world_.universe->info(object_).category;
    if (places.empty() || std::all_of(places.begin(), places.end(), [&](ObjectId p) { return p == here; })) {
      fail(out, MeaningFailure::kNoDestination, "That goal does not move " + noun + " from where it is.");
      return;
    }
    if (out.goal->satisfied_by(world_.state)) {
      fail(out, MeaningFailure::kAlreadyHolds, "That goal holds already.");
      return;
    }
    SearchOptions search;
    search.max_depth = options_.check_depth;
    search.max_nodes = options_.check_max_nodes;
    PlanResult plan = find_plan(*world_.domain, *world_.universe, world_.state, *out.goal, search);
    search_nodes_ += plan.statistics.nodes_expanded;
    if (plan.status != SearchStatus::kSolved)
      fail(out, MeaningFailure::kUnreachable, "I find no way to reach that goal.");
  }

  Understanding& understanding_;
  const World& world_;
  ObjectId object_;
  const GoalMemory& learned_;
  const GoalRepairOptions& options_;
  std::uint64_t search_nodes_ = 0;
};

// The destination a goal gives the object, as a key for agreement.
std::vector<ObjectId> destination_key(const World& world, const AnalysedGoal& goal, ObjectId object) {
  std::vector<ObjectId> key = destinations(world, *goal.goal, object);
  std::sort(key.begin(), key.end());
  return key;
}

// Step 5. Without it the statements keep their retrieval order, usable or
// not, for finalize_choice to sort as Algorithm 5 does.
void order(const World& world, ObjectId object, std::vector<AnalysedGoal>& all) {
  std::vector<AnalysedGoal> usable, unusable;
  for (AnalysedGoal& goal : all) (goal.goal ? usable : unusable).push_back(std::move(goal));
  // The same goal after repair is one goal, at its best position.
  std::vector<AnalysedGoal> merged;
  for (AnalysedGoal& goal : usable) {
    auto same = std::find_if(merged.begin(), merged.end(), [&](const AnalysedGoal& g) { return *g.goal == *goal.goal; });
    if (same == merged.end()) {
      merged.push_back(std::move(goal));
      continue;
    }
    same->merged.push_back(goal.position);
    same->weight += goal.weight;
  }
  std::map<std::vector<ObjectId>, double> agreement;
  for (const AnalysedGoal& goal : merged) agreement[destination_key(world, goal, object)] += goal.weight;
  for (AnalysedGoal& goal : merged) goal.score = agreement[destination_key(world, goal, object)];
  std::stable_sort(merged.begin(), merged.end(), [](const AnalysedGoal& a, const AnalysedGoal& b) {
    if (a.score != b.score) return a.score > b.score;
    if (a.weight != b.weight) return a.weight > b.weight;
    return a.position < b.position;
  });
  all = std::move(merged);
  for (AnalysedGoal& goal : unusable) all.push_back(std::move(goal));
}

}  // namespace

GoalAnalysis analyse_goals(Understanding& understanding, const World& world, ObjectId object,
                           const std::vector<llm::Candidate>& candidates, const GoalMemory& learned,
                           const GoalRepairOptions& options) {
  Analyser analyser(understanding, world, object, learned, options);
  GoalAnalysis analysis;
  for (std::size_t i = 0; i < candidates.size(); ++i)
    analysis.goals.push_back(analyser.analyse(candidates[i], static_cast<int>(i)));
  double total = 0.0;  // of the usable statements, before merging
  for (const AnalysedGoal& goal : analysis.goals)
    if (goal.goal) total += goal.weight;
  if (options.choose) {
    order(world, object, analysis.goals);
  } else {
    for (AnalysedGoal& goal : analysis.goals) goal.score = goal.weight;
  }
  for (AnalysedGoal& goal : analysis.goals) goal.share = total > 0.0 && goal.goal ? goal.score / total : 0.0;
  analysis.search_nodes = analyser.search_nodes();
  return analysis;
}

std::string describe_repairs(const World& world, const AnalysedGoal& goal) {
  std::string out;
  for (const std::string& clause : goal.dropped) out += (out.empty() ? "left out " : ", ") + clause;
  for (std::size_t i = 0; i < goal.closings.size(); ++i)
    out += std::string(out.empty() ? "" : "; ") + "added that " + language::noun_for(world, goal.closings[i]) +
           " is closed (" + (goal.closing_by_norm[i] ? "close what you opened" : "as the goals learned for it") + ")";
  return out;
}

std::string door_key(const World& world, ObjectId place) {
  const ObjectInfo& info = world.universe->info(place);
  if (world.universe->with_category(info.category).size() < 2) return info.category;
  std::string key;
  for (const std::string& p : info.properties) key += p + " ";
  return key + info.category;
}

std::vector<GoalKnowledge> goals_closing(const World& world, const GoalMemory& learned, ObjectId place,
                                         const std::string& said) {
  const std::string& in = world.domain->predicates[world.vocabulary.in].name;
  const std::string& closed = world.domain->predicates[world.vocabulary.closed].name;
  std::vector<GoalKnowledge> out;
  for (const GoalKnowledge& g : learned.all()) {
    auto into = std::find_if(g.literals.begin(), g.literals.end(), [&](const GoalTemplateLiteral& l) {
      return l.positive && l.predicate == in && l.arguments.size() == 2 && argument_fits(world, l.arguments[1], place);
    });
    if (into == g.literals.end()) continue;
    auto its_door = [&](const GoalTemplateLiteral& l) {
      return l.predicate == closed && l.arguments.size() == 1 && argument_fits(world, l.arguments[0], place);
    };
    if (std::any_of(g.literals.begin(), g.literals.end(), [&](const GoalTemplateLiteral& l) { return l.positive && its_door(l); }))
      continue;
    GoalKnowledge closing = g;
    const GoalTemplateArgument door = into->arguments[1];
    std::erase_if(closing.literals, its_door);
    closing.literals.push_back(GoalTemplateLiteral{closed, true, {door}});
    closing.provenance.source += " (" + language::spoken_name(world, place) + " closed from then on, as said: " +
                                 apprentice::quoted(said) + ")";
    out.push_back(std::move(closing));
  }
  return out;
}

std::vector<GoalKnowledge> goals_leaving_open(const World& world, const GoalMemory& learned, ObjectId place,
                                              const std::string& said) {
  const std::string& closed = world.domain->predicates[world.vocabulary.closed].name;
  auto closes_it = [&](const GoalTemplateLiteral& l) {
    return l.positive && l.predicate == closed && l.arguments.size() == 1 && argument_fits(world, l.arguments[0], place);
  };
  std::vector<GoalKnowledge> out;
  for (const GoalKnowledge& g : learned.all()) {
    if (std::none_of(g.literals.begin(), g.literals.end(), closes_it)) continue;
    GoalKnowledge open = g;
    std::erase_if(open.literals, closes_it);
    open.provenance.source += " (" + language::spoken_name(world, place) + " left open from then on, as said: " +
                              apprentice::quoted(said) + ")";
    out.push_back(std::move(open));
  }
  return out;
}

}  // namespace apprentice
