#include "language/grounding.h"

#include <algorithm>

#include <spdlog/spdlog.h>

#include "language/generation.h"
#include "language/narration.h"
#include "language/parser.h"
#include "language/reference.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language {
namespace {

// "recycling-bin" -> "recycling bin", as the instructor says it.
std::string spoken(const World& world, ObjectId id) {
  std::string name = world.universe->info(id).category;
  std::replace(name.begin(), name.end(), '-', ' ');
  return name;
}

GroundingFailure affordance(const World& world, std::string_view affordance_name, ObjectId id,
                            std::string message) {
  return {FailureKind::kAffordanceMismatch, std::string(affordance_name) + " " + world.universe->name(id),
          std::move(message)};
}

// Grounds the noun phrases of one sentence, remembering how.
class Session {
 public:
  Session(const World& world, const Lexicon& lexicon, std::optional<ObjectId> object_of_interest,
          Interpretation& out)
      : world_(world), lexicon_(lexicon), ooi_(object_of_interest), out_(out) {}

  // The object a phrase names, or the failure to put in `out_.result`.
  std::optional<ObjectId> object(const NounPhrase& np, Role role, std::optional<ObjectId> located_at = {}) {
    Resolution r = resolve(np, role, ReferenceContext{world_, lexicon_, ooi_, located_at});
    if (auto* failure = std::get_if<GroundingFailure>(&r)) {
      fail(std::move(*failure));
      return std::nullopt;
    }
    auto& reference = std::get<Reference>(r);
    out_.references.push_back(reference);
    return reference.object;
  }

  void fail(GroundingFailure failure) { failure_ = std::move(failure); }
  bool failed() const { return failure_.has_value(); }
  GroundingFailure take_failure() { return std::move(*failure_); }

  void bind(std::optional<ObjectId> object) {
    ooi_ = object;
    out_.bound_object = object;
  }

  Grounding goal(const GoalDescription& g);
  Grounding action(const ActionCommand& a);
  Grounding place_step(TaskStep step, Relation relation, const NounPhrase& place);

 private:
  std::optional<Literal> conjunct(const Conjunct& c);
  std::optional<ActionSchemaId> schema(std::string_view name);
  Grounding open_or_close(const ActionCommand& a);
  Grounding pick_up(ObjectId thing, std::optional<ObjectId> place);
  std::optional<ObjectId> item(const NounPhrase& np, std::optional<ObjectId> located_at = {});
  bool fits_relation(ObjectId place, Relation relation);

  const World& world_;
  const Lexicon& lexicon_;
  std::optional<ObjectId> ooi_;
  Interpretation& out_;
  std::optional<GroundingFailure> failure_;
};

// An item to move: anything else is an affordance mismatch.
std::optional<ObjectId> Session::item(const NounPhrase& np, std::optional<ObjectId> located_at) {
  auto id = object(np, Role::kItem, located_at);
  if (!id) return std::nullopt;
  if (world_.universe->info(*id).kind != ObjectKind::kItem) {
    fail(affordance(world_, "grabbable", *id, capitalize("the " + spoken(world_, *id) + " cannot be moved.")));
    return std::nullopt;
  }
  return id;
}

// Things go in receptacles and on surfaces.
bool Session::fits_relation(ObjectId place, Relation relation) {
  ObjectKind kind = world_.universe->info(place).kind;
  std::string name = spoken(world_, place);
  bool in = relation == Relation::kIn;
  if (in ? kind == ObjectKind::kReceptacle : kind == ObjectKind::kSurface) return true;
  std::string message = kind == ObjectKind::kItem
                            ? "The " + name + " is not a place to put things " + (in ? "in." : "on.")
                            : "Things go " + std::string(in ? "on" : "in") + " the " + name + ", not " +
                                  (in ? "in" : "on") + " it.";
  fail(affordance(world_, in ? "receptacle" : "surface", place, message));
  return false;
}

std::optional<Literal> Session::conjunct(const Conjunct& c) {
  const Vocabulary& v = world_.vocabulary;
  if (const auto* p = std::get_if<Placement>(&c)) {
    auto thing = item(p->thing);
    if (!thing) return std::nullopt;
    auto place = object(p->place, Role::kPlace);
    if (!place || !fits_relation(*place, p->relation)) return std::nullopt;
    return Literal{Fact(p->relation == Relation::kIn ? v.in : v.on, {*thing, *place}), true};
  }
  const auto& s = std::get<PropertyStatement>(c);
  if (s.property == Property::kUnknown) {
    std::string words = join(s.words, " ");
    fail({FailureKind::kUnknownPredicate, words,
          "I do not know what it means for the " + s.thing.text() + " to be " + words + "."});
    return std::nullopt;
  }
  auto thing = object(s.thing, Role::kPlace);
  if (!thing) return std::nullopt;
  bool closed = s.property == Property::kClosed;
  if (!openable(world_, *thing)) {
    std::string name = spoken(world_, *thing);
    std::string message = world_.universe->info(*thing).kind == ObjectKind::kReceptacle
                              ? "The " + name + " has no lid, so it can't be " + (closed ? "closed." : "open.")
                              : "The " + name + " can't be " + (closed ? "closed." : "opened.");
    fail(affordance(world_, closed ? "closed" : "open", *thing, message));
    return std::nullopt;
  }
  return Literal{Fact(v.closed, {*thing}), closed};
}

Grounding Session::goal(const GoalDescription& g) {
  if (g.category) {
    auto category = resolve_category(*g.category, ReferenceContext{world_, lexicon_, ooi_});
    if (auto* failure = std::get_if<GroundingFailure>(&category)) return *failure;
    const std::string& name = std::get<std::string>(category);
    if (ooi_ && world_.universe->info(*ooi_).category != name) {
      return GroundingFailure{FailureKind::kUngroundedObject, name,
                              "The object I am attending to is a " + world_.universe->info(*ooi_).category +
                                  ", not a " + name + "."};
    }
    if (!ooi_) ooi_ = world_.universe->with_category(name).front();
  }
  bind(ooi_);
  std::vector<Literal> literals;
  for (const Conjunct& c : g.conjuncts) {
    auto literal = conjunct(c);
    if (!literal) return take_failure();
    literals.push_back(*literal);
  }
  return Goal(std::move(literals));
}

std::optional<ActionSchemaId> Session::schema(std::string_view name) {
  auto id = world_.domain->find_action(name);
  if (!id) fail({FailureKind::kUnknownWord, std::string(name), "I do not know how to " + std::string(name) + "."});
  return id;
}

// "Open the fridge." / "Close the fridge.": a receptacle with a door.
Grounding Session::open_or_close(const ActionCommand& a) {
  bool open = a.verb == ActionVerb::kOpen;
  auto id = schema(open ? "open" : "close");
  auto target = id ? object(a.object, Role::kPlace) : std::nullopt;
  if (!target) return take_failure();
  bool receptacle = world_.universe->info(*target).kind == ObjectKind::kReceptacle;
  if (!receptacle || !openable(world_, *target)) {
    std::string name = spoken(world_, *target);
    return affordance(world_, "openable", *target,
                      "The " + name +
                          (receptacle ? " has no lid, so it can't be " + std::string(open ? "opened." : "closed.")
                                      : " can't be " + std::string(open ? "opened." : "closed.")));
  }
  ObjectId args[] = {*target};
  return Action(*id, args);
}

// pick-up from a surface, pick-up-from a receptacle: where the item is, or
// the place the sentence names.
Grounding Session::pick_up(ObjectId thing, std::optional<ObjectId> place) {
  if (!place) {
    place = place_of(world_, thing);
    if (!place)
      return GroundingFailure{FailureKind::kUngroundedObject, "location of " + world_.universe->name(thing),
                              "The " + spoken(world_, thing) + " is not on or in anything I can see."};
  }
  ObjectKind kind = world_.universe->info(*place).kind;
  if (kind == ObjectKind::kItem)
    return affordance(world_, "place", *place, "The " + spoken(world_, *place) + " is not a place.");
  auto id = schema(kind == ObjectKind::kSurface ? "pick-up" : "pick-up-from");
  if (!id) return take_failure();
  ObjectId args[] = {thing, *place};
  return Action(*id, args);
}

Grounding Session::action(const ActionCommand& a) {
  if (a.verb == ActionVerb::kOpen || a.verb == ActionVerb::kClose) return open_or_close(a);
  // "from the table" tells which plate; "in the fridge" does not.
  std::optional<ObjectId> place;
  if (a.destination) {
    place = object(*a.destination, Role::kPlace);
    if (!place) return take_failure();
  }
  auto thing = item(a.object, a.preposition == ActionPreposition::kFrom ? place : std::nullopt);
  if (!thing) return take_failure();
  if (a.verb == ActionVerb::kPickUp) return pick_up(*thing, place);
  if (!place)
    return GroundingFailure{FailureKind::kUninterpretable, "expected a place",
                            "Where should I put the " + spoken(world_, *thing) + "?"};
  Relation relation = a.preposition == ActionPreposition::kOn ? Relation::kOn : Relation::kIn;
  if (!fits_relation(*place, relation)) return take_failure();
  auto id = schema(relation == Relation::kOn ? "put-on" : "put-in");
  if (!id) return take_failure();
  ObjectId args[] = {*thing, *place};
  return Action(*id, args);
}

// A kind of place of which there are several here means all of them ("an
// object that is in a bag"); otherwise the phrase must name one place.
Grounding Session::place_step(TaskStep step, Relation relation, const NounPhrase& place) {
  std::vector<ObjectId> places;
  auto found = candidates_for(place, Role::kPlace, ReferenceContext{world_, lexicon_, ooi_});
  if (const auto* c = std::get_if<CandidateSet>(&found); c && c->objects.size() > 1) {
    const Universe& u = *world_.universe;
    bool one_kind = std::all_of(c->objects.begin(), c->objects.end(), [&](ObjectId id) {
      return u.info(id).kind != ObjectKind::kItem && u.info(id).category == u.info(c->objects.front()).category;
    });
    if (one_kind) {
      places = c->objects;
      for (ObjectId id : places) out_.references.push_back(Reference{place.text(), id, c->method, c->reason});
    }
  }
  if (places.empty()) {
    auto id = object(place, Role::kPlace);
    if (!id) return take_failure();
    places.push_back(*id);
  }
  for (ObjectId id : places)
    if (!fits_relation(id, relation)) return take_failure();
  step.relation = relation;
  step.place = places.front();
  step.places = std::move(places);
  return step;
}

struct FormGrounder {
  Session& session;
  Grounding operator()(const TaskName& t) const {
    return TaskStep{TaskStep::Kind::kTaskName, join(t.words, " "), Relation::kOn, std::nullopt, false};
  }
  Grounding operator()(const RepeatWhile& r) const {
    return session.place_step(TaskStep{TaskStep::Kind::kRepeatWhile, "", r.relation, std::nullopt, false},
                              r.relation, r.place);
  }
  Grounding operator()(const SubtaskCommand& s) const {
    return session.place_step(TaskStep{TaskStep::Kind::kSubtask, s.verb, s.relation, std::nullopt, false},
                              s.relation, s.place);
  }
  Grounding operator()(const Done&) const { return TaskStep{TaskStep::Kind::kDone, "", Relation::kOn, {}, false}; }
  Grounding operator()(const Repeat&) const { return TaskStep{TaskStep::Kind::kRepeat, "", Relation::kOn, {}, false}; }
  Grounding operator()(const Answer& a) const { return TaskStep{TaskStep::Kind::kAnswer, "", Relation::kOn, {}, a.yes}; }
  Grounding operator()(const GoalDescription& g) const { return session.goal(g); }
  Grounding operator()(const ActionCommand& a) const { return session.action(a); }
};

Interpretation uninterpretable(std::optional<LogicalForm> form, std::string detail, std::string message) {
  Interpretation out;
  out.form = std::move(form);
  out.result = GroundingFailure{FailureKind::kUninterpretable, std::move(detail), std::move(message)};
  return out;
}

}  // namespace

Interpretation Grounder::ground(const LogicalForm& form, const World& world,
                                std::optional<ObjectId> object_of_interest) const {
  Interpretation out;
  out.form = form;
  Session session(world, lexicon_, object_of_interest, out);
  out.result = std::visit(FormGrounder{session}, form);
  return out;
}

namespace {

// The sentence with the world's names that hold function words joined
// ("the walk in pantry" -> "the walk-in-pantry"), so that the grammar never
// reads their "in" or "and" as structure.
Result<LogicalForm> parse_in(std::string_view sentence, const World& world) {
  if (sentence.size() > kMaxSentenceBytes) return parse(sentence);
  std::vector<std::string> words = tokenize(sentence);
  std::vector<std::string> joined = words;
  join_world_names(joined, *world.universe);
  if (joined == words) return parse(sentence);
  return parse(join(joined, " "));
}

}  // namespace

Interpretation Grounder::interpret(std::string_view sentence, const World& world,
                                   std::optional<ObjectId> object_of_interest) const {
  auto form = parse_in(sentence, world);
  if (!form) return uninterpretable(std::nullopt, form.error().message, "I do not understand: " + form.error().message + ".");
  return ground(*form, world, object_of_interest);
}

Interpretation Grounder::interpret_goal(std::string_view sentence, const World& world,
                                        std::optional<ObjectId> object_of_interest) const {
  auto form = parse_in(sentence, world);
  if (!form) return uninterpretable(std::nullopt, form.error().message, "I do not understand: " + form.error().message + ".");
  if (!std::holds_alternative<GoalDescription>(*form))
    return uninterpretable(*form, "expected a goal", "I expected a goal, such as 'the goal is that ...'.");
  return ground(*form, world, object_of_interest);
}

Interpretation Grounder::interpret_action(std::string_view sentence, const World& world,
                                          std::optional<ObjectId> object_of_interest) const {
  auto form = parse_in(sentence, world);
  if (!form) return uninterpretable(std::nullopt, form.error().message, "I do not understand: " + form.error().message + ".");
  if (const auto* task = std::get_if<TaskName>(&*form)) {
    Interpretation out;
    out.form = *form;
    out.result = GroundingFailure{FailureKind::kUnknownWord, task->words.front(),
                                  "I do not know how to " + task->words.front() + "."};
    return out;
  }
  if (!std::holds_alternative<ActionCommand>(*form))
    return uninterpretable(*form, "expected an action", "I expected an action, such as 'Open the fridge.'.");
  return ground(*form, world, object_of_interest);
}

std::string format_grounding(const World& world, const Grounding& grounding) {
  if (const auto* goal = std::get_if<Goal>(&grounding))
    return "goal " + format_goal(*world.domain, *world.universe, *goal);
  if (const auto* action = std::get_if<Action>(&grounding))
    return "action " + format_action(*world.domain, *world.universe, *action);
  if (const auto* failure = std::get_if<GroundingFailure>(&grounding))
    return "failure " + std::string(to_string(failure->kind)) + " " + failure->detail;
  const auto& step = std::get<TaskStep>(grounding);
  auto where = [&] {
    return std::string(to_string(step.relation)) + " " + (step.place ? world.universe->name(*step.place) : "?");
  };
  switch (step.kind) {
    case TaskStep::Kind::kTaskName: return "task " + step.name;
    case TaskStep::Kind::kRepeatWhile: return "repeat-while " + where();
    case TaskStep::Kind::kSubtask: return "subtask " + step.name + " " + where();
    case TaskStep::Kind::kDone: return "done";
    case TaskStep::Kind::kRepeat: return "repeat";
    case TaskStep::Kind::kAnswer: return step.yes ? "answer yes" : "answer no";
  }
  return "done";
}

}  // namespace apprentice::language
