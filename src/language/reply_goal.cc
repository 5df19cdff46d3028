// Goals and actions in everyday English (language/reply_reading.h).
//
// Each clause of a reply becomes at most one event: a placement (the thing
// goes in or on a place), a door to close or open (said as a command or as
// a state, "with the door closed"), or a pick-up. A goal is the placements
// of the object asked about and the doors' states; an action is each event
// as a step. Events are grounded by the grammar's grounder
// (language/grounding.h), on logical forms whose noun phrases are the ids
// already resolved here, so that affordances are checked, and explained,
// in one place.
#include <algorithm>

#include "language/generation.h"
#include "language/narration.h"
#include "language/reply_reading.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language {
namespace {

struct Event {
  enum class Kind { kPlace, kOpen, kClose, kPick };
  Kind kind = Kind::kPlace;
  std::optional<ObjectId> item;   // kPlace, kPick
  bool item_named = false;        // said by its name, not as "it" or left out
  std::string item_words;         // as said: "the glass"
  std::optional<ObjectId> place;  // kPlace: where; kOpen/kClose: what; kPick: from where
  Relation relation = Relation::kIn;
  bool state = false;  // "the door closed", "leave it open": a state, not a command
};

using Events = std::variant<std::vector<Event>, Ambiguous, Problem>;


NounPhrase id_phrase(const World& world, ObjectId id) { return NounPhrase{"", {world.universe->name(id)}}; }

class EventReader {
 public:
  explicit EventReader(const ReplyInput& in) : in_(in), resolver_(in) {}

  Events read() {
    std::vector<Event> events;
    // "plates, forks and glasses go in the dishwasher", "put the plates
    // and the forks in the dishwasher": things named in clauses of their
    // own, before the clause that says where they go, go there too (in a
    // goal; an action is one step at a time).
    std::vector<Chunk> waiting;
    bool unplaced_before_waiting = false;
    for (const Clause& clause : read_clauses(in_.words, in_.vocabulary)) {
      clause_ = &clause;
      std::optional<Choice> failure;
      if (waiting.empty()) unplaced_before_waiting = unplaced_;
      std::optional<Event> event = read_clause(failure);
      if (event) events.push_back(*event);
      if (failure) return as_events(std::move(*failure));
      if (in_.context.asked == Asked::kGoal) {
        if (auto thing = waits_for_a_place(clause, event)) {
          waiting.push_back(*thing);
        } else if (event && event->kind == Event::Kind::kPlace) {
          // In the order said: the things waiting, then this clause's.
          events.pop_back();
          for (const Chunk& thing : waiting) {
            Event same = *event;
            same.item_words = thing.text();
            same.item = item(thing, same.item_named, failure);
            if (failure) return as_events(std::move(*failure));
            events.push_back(same);
          }
          // ("rake and shovel, they all go on the lower shelf": "they" is
          // the things waiting, not the thing asked about.)
          const bool pronoun = (clause.subject && clause.subject->pronoun) || (clause.object && clause.object->pronoun);
          if (waiting.empty() || !pronoun || event->item_named) events.push_back(*event);
          if (!waiting.empty()) unplaced_ = unplaced_before_waiting;  // "put the plates" has its place now
          waiting.clear();
        }
      }
      if (!clause.verb.empty() && clause.verb_class() == VerbClass::kNone && !clause.copula) unknown_verbs_.push_back(clause.verb);
    }
    return events;
  }

  const std::vector<std::string>& unknown_verbs() const { return unknown_verbs_; }
  // A placing verb was said without a place ("put it away").
  bool unplaced() const { return unplaced_; }

 private:
  // The thing a clause names without saying where it goes, and without
  // anything else: "plates" in "plates, forks and glasses go ...", "put
  // the plates" in "put the plates and the forks in ...". A place said on
  // its own is a placement (read_clause), not this.
  std::optional<Chunk> waits_for_a_place(const Clause& c, const std::optional<Event>& event) const {
    if (event || c.negated || c.closed || !c.phrases.empty() || !c.others.empty()) return std::nullopt;
    const std::optional<Chunk>* thing = nullptr;
    if (c.verb.empty() && !c.copula && c.subject && !c.object) thing = &c.subject;
    else if (c.verb_class() == VerbClass::kPlace && c.object && !c.subject) thing = &c.object;
    if (thing == nullptr || (*thing)->pronoun || (*thing)->place_pronoun || (*thing)->words.empty()) return std::nullopt;
    if (names_place(**thing) && !names_asked_kind(**thing)) return std::nullopt;
    return **thing;
  }

  // A failed choice as the reader's outcome: the question, or the problem.
  static Events as_events(Choice failure) {
    if (auto* ambiguous = std::get_if<Ambiguous>(&failure)) return std::move(*ambiguous);
    return std::get<Problem>(std::move(failure));
  }

  // A place from a phrase, remembered as the place named last.
  std::optional<ObjectId> place(const Chunk& chunk, std::optional<Choice>& failure, bool recent = true) {
    Choice choice = resolver_.choose(chunk, Role::kPlace, recent);
    if (const auto* id = std::get_if<ObjectId>(&choice)) {
      resolver_.named_place(*id);
      return *id;
    }
    failure = std::move(choice);
    return std::nullopt;
  }

  // The item of a placement or pick-up: the phrase, or the object asked
  // about when none is said. A named thing that is not the object asked
  // about is kept as said (the goal reader refuses it).
  std::optional<ObjectId> item(std::optional<Chunk> chunk, bool& named, std::optional<Choice>& failure) {
    // "with the other condiments": other things, not the one that goes.
    if (chunk && std::any_of(chunk->words.begin(), chunk->words.end(),
                             [](const std::string& w) { return w == "other" || w == "else"; }))
      chunk.reset();
    named = chunk && !chunk->pronoun;
    if (!chunk) {
      if (in_.context.object) return in_.context.object;
      failure = Problem{"Which thing do you mean? Please name it.", std::nullopt};
      return std::nullopt;
    }
    // "the candy wrapper is trash, it goes in the wastebasket": "it" after
    // another thing was named is that thing.
    if (chunk->pronoun && chunk->words.empty() && other_named_) {
      named = true;
      return other_named_;
    }
    Choice choice = resolver_.choose(*chunk, Role::kItem);
    if (const auto* id = std::get_if<ObjectId>(&choice); id && (*id == in_.context.object || !in_.context.object))
      return *id;
    // A name that fits the object asked about in other words ("the paper"
    // for the newspaper) is about it.
    if (in_.context.asked == Asked::kGoal && resolver_.fits_asked(*chunk)) return *in_.context.object;
    if (const auto* id = std::get_if<ObjectId>(&choice)) {
      if (!chunk->pronoun) other_named_ = *id;
      return *id;
    }
    // A goal names the object asked about; look-alikes of another kind do
    // not make the reply ambiguous, only not about it.
    if (const auto* ambiguous = std::get_if<Ambiguous>(&choice); ambiguous && in_.context.asked == Asked::kGoal)
      return ambiguous->candidates.front();
    failure = std::move(choice);
    return std::nullopt;
  }

  // Whether a phrase may name the kind of the thing asked about.
  bool names_asked_kind(const Chunk& chunk) const {
    if (!in_.context.object || chunk.pronoun) return false;
    auto found = resolver_.candidates(chunk, Role::kItem);
    const auto* objects = std::get_if<std::vector<ObjectId>>(&found);
    const std::string& kind = in_.world.universe->info(*in_.context.object).category;
    return objects && std::any_of(objects->begin(), objects->end(),
                                  [&](ObjectId id) { return in_.world.universe->info(id).category == kind; });
  }

  // Whether a phrase names a place here (without committing to it).
  bool names_place(const Chunk& chunk) const {
    if (chunk.pronoun) return false;
    auto found = resolver_.candidates(chunk, Role::kPlace);
    const auto* objects = std::get_if<std::vector<ObjectId>>(&found);
    return objects && std::any_of(objects->begin(), objects->end(), [&](ObjectId id) {
             return in_.world.universe->info(id).kind != ObjectKind::kItem;
           });
  }

  // The relation a preposition and a place make: a surface holds things on
  // it, a receptacle in it. "on" a receptacle without a door ("on the dish
  // rack", "on the shelf") is read as in it; "on" a receptacle with a door
  // and "in" a surface are kept, for the grounder to explain.
  Relation relation(std::optional<Preposition> preposition, ObjectId place, const Chunk& said) const {
    ObjectKind kind = in_.world.universe->info(place).kind;
    // "on the top shelf of the fridge": "on" is about the shelf.
    std::vector<std::string> name = name_parts(in_.world.universe->info(place).category);
    bool described = std::any_of(said.words.begin(), said.words.end(), [&](const std::string& w) {
      return std::find(name.begin(), name.end(), w) == name.end() && !in_.vocabulary.is_property(w) &&
             w != in_.world.universe->name(place);
    });
    if (described && !said.pronoun) preposition.reset();
    if (preposition == Preposition::kIn) return Relation::kIn;
    if (preposition == Preposition::kOn)
      return kind == ObjectKind::kReceptacle && !openable(in_.world, place) ? Relation::kIn : Relation::kOn;
    return kind == ObjectKind::kSurface ? Relation::kOn : Relation::kIn;
  }

  std::optional<Event> read_clause(std::optional<Choice>& failure) {
    const Clause& c = *clause_;
    VerbClass verb = c.verb_class();
    if ((verb == VerbClass::kClose || verb == VerbClass::kOpen) && !c.closed) return door(c, verb, failure);
    std::optional<Event> state;
    if (c.closed) {
      state = door_state(c, failure);
      if (failure) return std::nullopt;
    }
    if (auto placed = placement(c, verb, failure); placed || failure) return placed;
    if (state) return state;
    if (verb == VerbClass::kPick) return pick(c, failure);
    return std::nullopt;
  }

  // "close the fridge", "shut it", "open the cupboard door".
  std::optional<Event> door(const Clause& c, VerbClass verb, std::optional<Choice>& failure) {
    if (c.negated) return std::nullopt;  // "don't close it" asks nothing
    Chunk target;
    if (c.object) target = *c.object;
    else if (!c.phrases.empty() && !c.phrases.front().noun.empty()) target = c.phrases.front().noun;
    else target.pronoun = true;
    auto id = place(target, failure);
    if (!id) return std::nullopt;
    Event event;
    event.kind = verb == VerbClass::kClose ? Event::Kind::kClose : Event::Kind::kOpen;
    event.place = id;
    return event;
  }

  // "with the door closed", "the fridge should be shut", "leave it open",
  // "don't leave the door open".
  std::optional<Event> door_state(const Clause& c, std::optional<Choice>& failure) {
    Chunk target;
    if (c.subject && (c.subject->pronoun || names_place(*c.subject) || !c.object)) target = *c.subject;
    else if (c.object) target = *c.object;
    else target.pronoun = true;
    if (target.pronoun || target.words.empty()) target = Chunk::it();
    auto id = place(target, failure);
    if (!id) return std::nullopt;
    Event event;
    event.kind = *c.closed != c.negated ? Event::Kind::kClose : Event::Kind::kOpen;
    event.place = id;
    event.state = true;
    return event;
  }

  // Where the thing goes: the last "in/on/to" phrase, a place implied by
  // the verb ("throw it away", "recycle it"), or a place said on its own
  // ("fridge", "that's trash", "the fridge is where it goes").
  std::optional<Event> placement(const Clause& c, VerbClass verb, std::optional<Choice>& failure) {
    // The destination: the last place phrase that names a place here ("in
    // the fridge on the door shelf": the shelf is a detail of the fridge).
    // A verb this reader does not know places things only "into" or
    // "onto" something ("unload it into the cupboard", not "walk to the
    // fridge", "wash it in the sink"); picking up "in"/"on" a place says
    // where the thing is, not where it goes.
    const PrepPhrase* destination = nullptr;
    bool known_verb = c.verb.empty() || c.copula || verb != VerbClass::kNone;
    for (const PrepPhrase& p : c.phrases) {
      if (p.preposition != Preposition::kIn && p.preposition != Preposition::kOn && p.preposition != Preposition::kTo)
        continue;
      // ("coil it up on the right hook", "roll them up in the bin": a
      // verb it does not know, with "up", "away" or "back", puts a thing
      // somewhere too.)
      bool moving = p.word == "into" || p.word == "onto" || p.word == "inside" ||
                    (!known_verb && is_one_of(c.particle, {"up", "away", "back"}) &&
                     (p.preposition == Preposition::kIn || p.preposition == Preposition::kOn));
      if (!known_verb && !moving) continue;
      if (verb == VerbClass::kPick && p.preposition != Preposition::kTo && !moving) continue;
      if (destination && !p.noun.empty() && !names_place(p.noun) && !destination->noun.empty() &&
          names_place(destination->noun))
        continue;
      destination = &p;
    }
    std::optional<Chunk> where;
    std::optional<Preposition> preposition;
    const std::optional<Chunk>* item_chunk = nullptr;
    bool imperative = verb == VerbClass::kPlace || verb == VerbClass::kDiscard || verb == VerbClass::kRecycle ||
                      verb == VerbClass::kPick;
    if (destination) {
      where = destination->noun.empty() ? Chunk::there() : destination->noun;
      preposition = destination->preposition;
      item_chunk = imperative && c.object ? &c.object : c.subject ? &c.subject : &c.object;
    } else if (verb == VerbClass::kDiscard || verb == VerbClass::kRecycle) {
      where = Chunk::of_words({verb == VerbClass::kDiscard ? "trash" : "recycling"});
      item_chunk = c.object ? &c.object : &c.subject;
    } else if (c.where && c.subject) {
      where = *c.subject;
      item_chunk = &c.object;
    } else if (!c.closed && (verb == VerbClass::kNone || verb == VerbClass::kBe) &&
               std::all_of(c.phrases.begin(), c.phrases.end(), [](const PrepPhrase& p) {
                 return p.preposition == Preposition::kOther || p.preposition == Preposition::kFrom;
               })) {
      // A place said on its own: the subject, or what follows "is". A
      // phrase that also names the asked thing's kind is that thing ("cans"
      // in "cans and bottles get recycled", not the trash can).
      if (c.subject && !c.object && names_place(*c.subject) && !names_asked_kind(*c.subject)) {
        where = *c.subject;
      } else if (c.object && c.copula && names_place(*c.object)) {
        where = *c.object;
        item_chunk = &c.subject;
      } else {
        return std::nullopt;
      }
    } else if (auto here = stays_put(c)) {
      where = *here;
      item_chunk = &c.object;
    } else if (auto implied = implied_place(c)) {
      where = *implied;
      item_chunk = c.object ? &c.object : &c.subject;
    } else {
      if (verb == VerbClass::kPlace && !c.negated && c.verb != "leave" && c.verb != "keep" && !c.closed)
        unplaced_ = true;
      return std::nullopt;
    }
    if (c.negated) return std::nullopt;  // "not in the pantry"
    // A destination named by kind among look-alikes ("in the drawer") is
    // asked which, even after a placement in one of them: the teacher may
    // mean the other.
    auto place_id = place(*where, failure, false);
    if (!place_id) {
      if (verb == VerbClass::kDiscard && !destination && std::holds_alternative<Problem>(*failure))
        failure = Problem{"I don't see a trash can here; where should it go?", std::nullopt};
      return std::nullopt;
    }
    Event event;
    event.place = place_id;
    event.relation = relation(preposition, *place_id, *where);
    std::optional<Chunk> none;
    const std::optional<Chunk>& said = item_chunk ? *item_chunk : none;
    if (said) event.item_words = said->text();
    event.item = item(said, event.item_named, failure);
    if (!event.item) return std::nullopt;
    return event;
  }

  // "leave it where it is", "leave it here", "it stays put": the place
  // the object asked about is at now.
  std::optional<Chunk> stays_put(const Clause& c) const {
    if (!in_.context.object || c.negated) return std::nullopt;
    if (c.verb != "leave" && c.verb != "keep" && c.verb != "stay") return std::nullopt;
    const std::vector<std::string>& w = c.words;
    auto has = [&](std::initializer_list<std::string_view> phrase) {
      return std::search(w.begin(), w.end(), phrase.begin(), phrase.end()) != w.end();
    };
    if (!(has({"where", "it", "is"}) || has({"where", "it", "was"}) || has({"here"}) || has({"alone"}) ||
          has({"put"}) || has({"as", "it", "is"}) || has({"where", "they", "are"})))
      return std::nullopt;
    auto place = place_of(in_.world, *in_.context.object);
    if (!place) return std::nullopt;
    return Chunk::of_words({in_.world.universe->name(*place)});
  }

  // A verb that names its place: "refrigerate it" (a refrigerator),
  // "recycle" (the recycling). The forms tried are the verb itself and its
  // agent and action nouns; one of them must name exactly one place here.
  std::optional<Chunk> implied_place(const Clause& c) const {
    if (c.verb.empty() || c.negated || c.closed) return std::nullopt;
    VerbClass kind = c.verb_class();
    if (kind != VerbClass::kPlace && kind != VerbClass::kNone) return std::nullopt;
    std::string stem = c.verb.ends_with("e") ? c.verb.substr(0, c.verb.size() - 1) : c.verb;
    for (const std::string& noun : {stem + "or", c.verb + "r", stem + "er", stem + "ing"}) {
      Chunk chunk = Chunk::of_words({noun});
      auto found = resolver_.candidates(chunk, Role::kPlace);
      const auto* ids = std::get_if<std::vector<ObjectId>>(&found);
      if (ids && ids->size() == 1 && in_.world.universe->info(ids->front()).kind != ObjectKind::kItem) return chunk;
    }
    return std::nullopt;
  }

  // "pick it up", "take the mug from the dish rack".
  std::optional<Event> pick(const Clause& c, std::optional<Choice>& failure) {
    Event event;
    event.kind = Event::Kind::kPick;
    for (const PrepPhrase& p : c.phrases)
      if (p.preposition == Preposition::kFrom && !p.noun.empty()) {
        event.place = place(p.noun, failure);
        if (!event.place) return std::nullopt;
      }
    event.item = item(c.object, event.item_named, failure);
    if (!event.item) return std::nullopt;
    return event;
  }

  const ReplyInput& in_;
  Resolver resolver_;
  const Clause* clause_ = nullptr;
  std::vector<std::string> unknown_verbs_;
  bool unplaced_ = false;
  // The last thing named that is not the one asked about: what "it" names
  // after it.
  std::optional<ObjectId> other_named_;
};

std::string said(const ReplyInput& in) { return quoted_words(in.words); }

Reply from_problem(const ReplyInput& in, Events events) {
  if (auto* ambiguous = std::get_if<Ambiguous>(&events)) return *ambiguous;
  return unusable(in, std::get<Problem>(events));
}

Problem failure_problem(const Interpretation& interpretation) {
  const GroundingFailure& failure = *interpretation.failure();
  return Problem{failure.message, failure};
}

}  // namespace

Reply read_goal(const ReplyInput& in) {
  EventReader reader(in);
  Events read = reader.read();
  if (!std::holds_alternative<std::vector<Event>>(read)) return from_problem(in, std::move(read));
  const auto& events = std::get<std::vector<Event>>(read);
  const World& world = in.world;
  std::optional<ObjectId> asked = in.context.object;
  std::string asked_noun = asked ? distinct_noun_for(world, *asked) : "it";
  GoalDescription goal;
  std::optional<ObjectId> destination;
  std::string other;
  // Other things placed by name ("forks" in "plates and forks go in the
  // dishwasher"): their goals come with the goal asked for.
  std::vector<const Event*> others;
  for (const Event& e : events) {
    if (e.kind == Event::Kind::kPlace) {
      if (asked && *e.item != *asked) {
        if (e.item_named && other.empty()) other = spoken_name(world, *e.item);
        if (e.item_named && std::none_of(others.begin(), others.end(), [&](const Event* o) { return o->item == e.item; }))
          others.push_back(&e);
        continue;
      }
      if (destination && *destination != *e.place)
        return unusable(in, Problem{"I can put " + asked_noun + " in only one place: " +
                                        say_alternatives({distinct_noun_for(world, *destination),
                                                          distinct_noun_for(world, *e.place)}) + "?",
                                    std::nullopt});
      if (!destination)
        goal.conjuncts.push_back(Placement{id_phrase(world, *e.item), e.relation, id_phrase(world, *e.place)});
      destination = e.place;
      if (!asked) asked = e.item;
    } else if (e.kind == Event::Kind::kClose || (e.kind == Event::Kind::kOpen && e.state)) {
      goal.conjuncts.push_back(PropertyStatement{id_phrase(world, *e.place),
                                                 e.kind == Event::Kind::kClose ? Property::kClosed : Property::kOpen,
                                                 {e.kind == Event::Kind::kClose ? "closed" : "open"}});
    }
  }
  if (!destination) {
    if (!other.empty())
      return unusable(in, Problem{"That says what becomes of " + other + ", but I asked about " +
                                      (asked ? spoken_name_and_location(world, *asked) : asked_noun) +
                                      ". Where should " + asked_noun + " go?",
                                  std::nullopt});
    // A door's state alone is checked first: it may be impossible.
    if (!goal.conjuncts.empty()) {
      Interpretation grounded = in.grounder.ground(goal, world, asked);
      if (!grounded.ok()) return unusable(in, failure_problem(grounded));
    }
    if (reader.unplaced())
      return unusable(in, Problem{"Where should " + asked_noun + " go? Please name the place.", std::nullopt});
    if (!reader.unknown_verbs().empty())
      return unusable(in, Problem{"I don't know how to " + reader.unknown_verbs().front() +
                                      " things; I need to know where " + asked_noun + " should end up.",
                                  std::nullopt});
    return unusable(in, Problem{"I didn't catch where " + asked_noun + " should go in \"" + said(in) + "\".",
                                std::nullopt});
  }
  // Placements first, as the grammar's goals have them.
  std::stable_partition(goal.conjuncts.begin(), goal.conjuncts.end(),
                        [](const Conjunct& c) { return std::holds_alternative<Placement>(c); });
  Interpretation grounded = in.grounder.ground(goal, world, asked);
  if (!grounded.ok()) return unusable(in, failure_problem(grounded));
  GoalGiven given{std::get<Goal>(grounded.result)};
  // Each other thing: its placement, and the same doors when it goes to the
  // same place. One that cannot
  // be so ("the plates and the milk go on the dish rack" where the milk
  // cannot) is left out; it is asked about when its turn comes.
  for (const Event* e : others) {
    GoalDescription same = goal;
    if (e->place != destination) same.conjuncts.resize(1);  // the doors said are of the other place
    std::get<Placement>(same.conjuncts.front()) =
        Placement{id_phrase(world, *e->item), e->relation, id_phrase(world, *e->place)};
    Interpretation theirs = in.grounder.ground(same, world, e->item);
    if (theirs.ok()) given.others.push_back(std::get<Goal>(theirs.result));
  }
  return given;
}

Reply read_action(const ReplyInput& in) {
  EventReader reader(in);
  Events read = reader.read();
  if (!std::holds_alternative<std::vector<Event>>(read)) return from_problem(in, std::move(read));
  const World& world = in.world;
  std::vector<Action> actions;
  for (const Event& e : std::get<std::vector<Event>>(read)) {
    ActionCommand command;
    switch (e.kind) {
      case Event::Kind::kOpen:
      case Event::Kind::kClose:
        command.verb = e.kind == Event::Kind::kOpen ? ActionVerb::kOpen : ActionVerb::kClose;
        command.object = id_phrase(world, *e.place);
        break;
      case Event::Kind::kPick:
        command.verb = ActionVerb::kPickUp;
        command.object = id_phrase(world, *e.item);
        if (e.place) {
          command.preposition = ActionPreposition::kFrom;
          command.destination = id_phrase(world, *e.place);
        }
        break;
      case Event::Kind::kPlace:
        command.verb = ActionVerb::kPut;
        command.object = id_phrase(world, *e.item);
        command.preposition = e.relation == Relation::kOn ? ActionPreposition::kOn : ActionPreposition::kIn;
        command.destination = id_phrase(world, *e.place);
        break;
    }
    Interpretation grounded = in.grounder.ground(command, world, in.context.object);
    if (!grounded.ok()) return unusable(in, failure_problem(grounded));
    actions.push_back(std::get<Action>(grounded.result));
  }
  if (actions.empty()) {
    if (reader.unplaced())
      return unusable(in, Problem{"Where should I put it? Please name the place.", std::nullopt});
    if (!reader.unknown_verbs().empty())
      return unusable(in, Problem{"I don't know how to " + reader.unknown_verbs().front() +
                                      " things; I can open, close, pick up and put down.",
                                  std::nullopt});
    return unusable(in, Problem{"I didn't catch what to do in \"" + said(in) + "\".", std::nullopt});
  }
  ActionGiven given;
  given.action = actions.front();
  given.more.assign(actions.begin() + 1, actions.end());
  return given;
}

}  // namespace apprentice::language
