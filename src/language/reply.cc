#include "language/reply.h"

#include <algorithm>
#include <set>

#include "language/generation.h"
#include "language/narration.h"
#include "language/parser.h"
#include "language/reply_acts_parts.h"
#include "language/reply_reading.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language {
namespace {

// The kind of object "forget" names: a category of the world when the words
// name one ("forget the glasses" -> "glass-tumbler"), else the words.
std::string kind_named(const Grounder& grounder, const World& world, std::vector<std::string> words) {
  std::erase_if(words, [](const std::string& w) { return is_determiner(w) || w == "about" || w == "everything"; });
  if (words.empty()) return "";
  // "the towel rule", "trash in the top drawer": a rule, named by its words
  // (the agent looks it up).
  if (is_one_of(words.back(), {"rule", "rules"})) return join(words, " ");
  if (std::any_of(words.begin() + 1, words.end(), [](const std::string& w) { return is_one_of(w, {"in", "on", "into", "onto"}); }))
    return join(words, " ");
  ReferenceContext context{world, grounder.lexicon(), std::nullopt};
  context.partial_names = true;
  auto found = candidates_for(NounPhrase{"", words}, Role::kItem, context);
  if (const auto* c = std::get_if<CandidateSet>(&found)) {
    std::set<std::string> categories;
    for (ObjectId id : c->objects) categories.insert(world.universe->info(id).category);
    if (categories.size() == 1) return *categories.begin();
  }
  return join(words, " ");
}


bool mentions(const Goal& goal, ObjectId object) {
  return std::any_of(goal.literals.begin(), goal.literals.end(),
                     [&](const Literal& l) { return l.fact.mentions(object); });
}

// The script's sentences, read by its grammar, where they answer the
// question: they keep the meaning the paper gives them.
std::optional<Reply> scripted(const Grounder& grounder, const World& world, const ReplyContext& context,
                              std::string_view text, std::optional<Problem>& failure) {
  if (context.asked == Asked::kTask || context.asked == Asked::kWhich) return std::nullopt;
  Interpretation in = grounder.interpret(text, world, context.object);
  if (!in.form) return std::nullopt;
  bool structure = context.asked == Asked::kTaskStep || context.asked == Asked::kSubtaskEnd;
  const LogicalForm& form = *in.form;
  bool fits = (structure && (std::holds_alternative<RepeatWhile>(form) || std::holds_alternative<SubtaskCommand>(form) ||
                             std::holds_alternative<Done>(form) || std::holds_alternative<Repeat>(form))) ||
              (context.asked == Asked::kGoal &&
               (std::holds_alternative<GoalDescription>(form) || std::holds_alternative<Done>(form))) ||
              (context.asked == Asked::kAction && std::holds_alternative<ActionCommand>(form)) ||
              (context.asked == Asked::kYesNo && std::holds_alternative<Answer>(form));
  if (!fits) return std::nullopt;
  if (const auto* f = in.failure()) {
    failure = Problem{f->message, *f};
    return std::nullopt;
  }
  if (const auto* goal = std::get_if<Goal>(&in.result)) {
    if (context.object && !mentions(*goal, *context.object)) return std::nullopt;
    return GoalGiven{*goal};
  }
  if (const auto* action = std::get_if<Action>(&in.result)) {
    ActionGiven given;
    given.action = *action;
    return given;
  }
  const auto& step = std::get<TaskStep>(in.result);
  switch (step.kind) {
    case TaskStep::Kind::kRepeatWhile: return LoopNamed{step.relation, step.places};
    case TaskStep::Kind::kSubtask: return SubtaskNamed{step.name, step.relation, step.places};
    case TaskStep::Kind::kDone: return Finished{};
    case TaskStep::Kind::kRepeat: return Proceed{};
    case TaskStep::Kind::kAnswer: return YesNo{step.yes, ""};
    case TaskStep::Kind::kTaskName: break;
  }
  return std::nullopt;
}

// --- Examples, from the world ---------------------------------------------------


// Places that hold something now, in id order.
std::vector<ObjectId> places_with_things(const World& world) {
  std::vector<ObjectId> out;
  for (ObjectId id = 0; id < world.universe->size(); ++id)
    if (world.universe->info(id).kind == ObjectKind::kItem)
      if (auto where = place_of(world, id); where && std::find(out.begin(), out.end(), *where) == out.end())
        out.push_back(*where);
  std::sort(out.begin(), out.end());
  return out;
}

// A place to put `object` other than where it is: a receptacle with a
// door when `with_door`, else a receptacle, else a surface.
std::optional<ObjectId> destination_for(const World& world, std::optional<ObjectId> object, bool with_door) {
  std::optional<ObjectId> here = object ? place_of(world, *object) : std::nullopt;
  std::optional<ObjectId> surface;
  for (ObjectId id = 0; id < world.universe->size(); ++id) {
    ObjectKind kind = world.universe->info(id).kind;
    if (kind == ObjectKind::kItem || id == here) continue;
    if (with_door && !(kind == ObjectKind::kReceptacle && openable(world, id))) continue;
    if (kind == ObjectKind::kSurface) {
      if (!surface) surface = id;
      continue;
    }
    return id;
  }
  return with_door ? std::nullopt : surface;
}

std::string in_or_on(const World& world, ObjectId place) {
  return world.universe->info(place).kind == ObjectKind::kSurface ? "on " : "in ";
}

std::string item_noun(const World& world, std::optional<ObjectId> object) {
  if (!object) {
    for (ObjectId id = 0; id < world.universe->size(); ++id)
      if (world.universe->info(id).kind == ObjectKind::kItem) return "the " + spoken_category(world, id);
    return "it";
  }
  return "the " + spoken_category(world, *object);
}

std::vector<std::string> structure_examples(const World& world, bool subtask_end) {
  std::vector<ObjectId> places = places_with_things(world);
  std::vector<std::string> out;
  if (subtask_end) out = {"that's all", "keep going"};
  for (std::size_t i = 0; i < places.size() && i < 2; ++i)
    out.push_back((i == 0 && !subtask_end ? "clear " : "then clear ") + distinct_noun_for(world, places[i]));
  if (!subtask_end) out.emplace_back("that's all");
  return out;
}

std::vector<std::string> goal_examples(const World& world, const ReplyContext& context) {
  std::vector<std::string> out;
  std::string item = item_noun(world, context.object);
  auto any = destination_for(world, context.object, false);
  auto with_door = destination_for(world, context.object, true);
  // "the crackers go", "the ketchup goes".
  bool plural = context.object && is_plural_category(world.universe->info(*context.object).category);
  if (any) out.push_back(item + (plural ? " go " : " goes ") + in_or_on(world, *any) + distinct_noun_for(world, *any));
  if (with_door)
    out.push_back("put " + std::string(plural ? "them" : "it") + " in " + distinct_noun_for(world, *with_door) +
                  " and close it");
  if (any) out.push_back(in_or_on(world, *any) + distinct_noun_for(world, *any));
  return out;
}

std::vector<std::string> action_examples(const World& world, const ReplyContext& context) {
  std::vector<std::string> out;
  std::optional<ObjectId> here = context.object ? place_of(world, *context.object) : std::nullopt;
  if (context.object && here) out.push_back("pick up " + item_noun(world, context.object));
  for (ObjectId id = 0; id < world.universe->size() && out.size() < 2; ++id)
    if (openable(world, id) && world.state.holds(Fact(world.vocabulary.closed, {id})))
      out.push_back("open " + distinct_noun_for(world, id));
  if (auto any = destination_for(world, context.object, false))
    out.push_back("put it " + in_or_on(world, *any) + distinct_noun_for(world, *any));
  return out;
}

}  // namespace

std::optional<Command> command(const Grounder& grounder, const World& world, std::string_view text) {
  std::vector<std::string> words = reply_words(text);
  std::erase_if(words, [](const std::string& w) { return w == "please"; });
  // "forget that, put it in the drawer" is never mind; "forget that paper
  // stuff rule" forgets the rule: told apart before the commas go.
  const bool forget_that_alone = words.size() >= 2 && words[0] == "forget" &&
                                 is_one_of(words[1], {"it", "that", "this"}) &&
                                 (words.size() == 2 || words[2] == "," || words[2] == ".");
  std::erase_if(words, [](const std::string& w) { return w == ","; });
  if (words.empty()) return std::nullopt;
  auto is = [&](std::initializer_list<std::string_view> phrase) {
    return words.size() == phrase.size() && std::equal(phrase.begin(), phrase.end(), words.begin());
  };
  if (is({"help"}) || is({"help", "me"}) || is({"what", "can", "i", "say"}) || is({"i", "need", "help"}) ||
      is({"what", "do", "i", "say"}) || is({"what", "should", "i", "say"}) || text == "?")
    return Command{Command::Kind::kHelp, ""};
  if (is({"status"}) || is({"where", "are", "we"}) || is({"what", "is", "the", "status"}) || is({"show", "status"}))
    return Command{Command::Kind::kStatus, ""};
  if (is({"undo"}) || is({"undo", "that"}) || is({"undo", "it"}) || is({"take", "that", "back"}) ||
      is({"scratch", "that"}) || is({"undo", "the", "last", "one"}) || is({"undo", "last"}))
    return Command{Command::Kind::kUndo, ""};
  if (is({"quit"}) || is({"exit"}) || is({"bye"}) || is({"goodbye"}) || is({"q"}))
    return Command{Command::Kind::kQuit, ""};
  // ("forget it", "forget that": never mind, not a kind to forget.)
  if (words[0] == "forget" && words.size() > 1 && !forget_that_alone) {
    std::vector<std::string> rest(words.begin() + 1, words.end());
    if (rest.size() > 1 && is_one_of(rest[0], {"that", "this", "about"})) rest.erase(rest.begin());
    if (rest.size() > 3 && rest[0] == "what" && rest[1] == "you" && rest[2] == "know") rest.erase(rest.begin(), rest.begin() + 3);
    std::string kind = kind_named(grounder, world, rest);
    if (!kind.empty()) return Command{Command::Kind::kForget, kind};
  }
  return std::nullopt;
}

std::string_view to_string(Asked asked) {
  switch (asked) {
    case Asked::kTask: return "task";
    case Asked::kTaskStep: return "task-step";
    case Asked::kSubtaskEnd: return "subtask-end";
    case Asked::kGoal: return "goal";
    case Asked::kAction: return "action";
    case Asked::kYesNo: return "yes-no";
    case Asked::kWhich: return "which";
  }
  return "task";
}

std::optional<Asked> asked_named(std::string_view name) {
  for (Asked asked : kEveryAsked)
    if (to_string(asked) == name) return asked;
  return std::nullopt;
}

namespace {

// A goal that leaves the thing asked about where it is ("leave it on the
// desk", "it stays on the tub") is leaving it alone.
bool stays_where_it_is(const World& world, const ReplyContext& context, const Reply& reply) {
  const auto* given = std::get_if<GoalGiven>(&reply);
  if (given == nullptr || !context.object || !given->others.empty()) return false;
  std::optional<ObjectId> here = place_of(world, *context.object);
  bool placed = false;
  for (const Literal& l : given->goal.literals) {
    if (l.fact.arity != 2 || (l.fact.predicate != world.vocabulary.in && l.fact.predicate != world.vocabulary.on))
      continue;
    if (l.fact.args[0] != *context.object || l.fact.args[1] != here) return false;
    placed = true;
  }
  return placed;
}

// The goal question's readings after its own: the thing left where it is,
// the rest of the things, and the readings by reference to others.
Reply read_goal_reply(const Grounder& grounder, const World& world, const ReplyContext& context,
                      std::string_view text, Reply reply) {
  if (stays_where_it_is(world, context, reply)) return Finished{};
  if (std::holds_alternative<GoalGiven>(reply))
    if (auto rest = read_goal_with_rest(grounder, world, context, text, reply)) return *rest;
  if (std::holds_alternative<Unusable>(reply) || std::holds_alternative<Ambiguous>(reply))
    if (auto other = read_goal_by_others(grounder, world, context, text, reply)) return *other;
  return reply;
}

// The goals a reply points to for the rest of its meaning: the goal given
// last when it says "too", "as well", "also" or "same"; the goal of each
// kind it names after "with", "like" or "as" ("in with the plates", "the
// doll goes in the toy chest with teddy", "fridge, same as the milk").
std::vector<Goal> referred_goals(const Grounder& grounder, const World& world, const ReplyContext& context,
                                 const std::vector<std::string>& words) {
  std::vector<Goal> out;
  if (!context.object) return out;
  bool additive = false;
  for (std::size_t i = 0; i < words.size(); ++i) {
    additive = additive || is_one_of(words[i], {"too", "also", "same", "ditto"}) ||
               (words[i] == "as" && i + 1 < words.size() && words[i + 1] == "well");
    if (!context.goal_of_kind || !is_one_of(words[i], {"with", "like", "as"})) continue;
    std::vector<std::string> noun;
    for (std::size_t j = i + 1; j < words.size() && words[j] != ","; ++j)
      if (!is_determiner(words[j])) noun.push_back(words[j]);
    if (noun.empty()) continue;
    ReferenceContext reference{world, grounder.lexicon(), std::nullopt};
    reference.partial_names = true;
    auto found = candidates_for(NounPhrase{"", noun}, Role::kItem, reference);
    if (const auto* set = std::get_if<CandidateSet>(&found))
      for (ObjectId o : set->objects)
        if (auto goal = context.goal_of_kind(world.universe->info(o).category, *context.object)) out.push_back(*goal);
  }
  if (additive && context.last_goal) out.push_back(context.last_goal->goal);
  return out;
}

// A goal said by reference to another ("dishwasher as well", "in with the
// plates") keeps what the other goal says of the door of the place they
// share, where the reply says nothing of it: "the plates go in the
// dishwasher, and it ends closed" makes "the bowl too" end closed as well.
void like_the_goal_referred_to(const Grounder& grounder, const World& world, const ReplyContext& context,
                               std::string_view text, Reply& reply) {
  auto* given = std::get_if<GoalGiven>(&reply);
  // "the milk in the fridge, and the cream too": "too" is about the cream.
  if (given == nullptr || !given->others.empty()) return;
  const Vocabulary& v = world.vocabulary;
  std::vector<Goal> referred = referred_goals(grounder, world, context, reply_words(text));
  auto complete = [&](Goal& goal) {
    std::vector<Literal> added;
    for (const Literal& l : goal.literals) {
      if (!l.positive || l.fact.arity != 2 || (l.fact.predicate != v.in && l.fact.predicate != v.on)) continue;
      const ObjectId place = l.fact.args[1];
      auto door = [&](const Literal& c) { return c.fact.predicate == v.closed && c.fact.args[0] == place; };
      if (std::any_of(goal.literals.begin(), goal.literals.end(), door)) continue;
      for (const Goal& other : referred) {
        bool shares = std::any_of(other.literals.begin(), other.literals.end(), [&](const Literal& o) {
          return o.positive && o.fact.arity == 2 && o.fact.predicate == l.fact.predicate && o.fact.args[1] == place;
        });
        auto said = std::find_if(other.literals.begin(), other.literals.end(), door);
        if (shares && said != other.literals.end()) {
          added.push_back(*said);
          break;
        }
      }
    }
    goal.literals.insert(goal.literals.end(), added.begin(), added.end());
  };
  if (referred.empty()) return;
  complete(given->goal);
}

}  // namespace

namespace {

// The one kind of thing (an item's category) that `words` name, by its
// name's words in turn, the last one maybe plural ("sticky notes"); none
// when they name no kind or several.
// A name said in part counts when no kind is named whole: its last words
// ("the leash" for the dog leash), and then a word WordNet gives as the
// kind's synonym ("the teddy" for the teddy bear). Of several kinds named,
// the one named first ("the stapler belongs in the bottom drawer with the
// headset").
std::optional<std::string> the_kind_named(const World& world, const Lexicon& lexicon, const std::vector<std::string>& words) {
  for (std::size_t first = 0; first < 3; ++first) {
    // Where each kind's name, from its part `first` on, is first said; the
    // longest name wins where two begin at one word.
    std::optional<std::size_t> at;
    std::size_t longest = 0;
    std::set<std::string> named;
    std::set<std::string> seen;
    for (ObjectId o : world.universe->of_kind(ObjectKind::kItem)) {
      const std::string& category = world.universe->info(o).category;
      const std::vector<std::string> whole = name_parts(category);
      if (first >= whole.size() || !seen.insert(category).second) continue;
      const std::vector<std::string> parts(whole.begin() + static_cast<std::ptrdiff_t>(first), whole.end());
      for (std::size_t i = 0; i + parts.size() <= words.size(); ++i) {
        bool match = true;
        for (std::size_t k = 0; k < parts.size() && match; ++k) {
          const std::string& w = words[i + k];
          match = w == parts[k] || (k + 1 == parts.size() && (w == parts[k] + "s" || w == parts[k] + "es"));
        }
        if (!match) continue;
        if (!at || i < *at || (i == *at && parts.size() > longest)) {
          at = i;
          longest = parts.size();
          named = {category};
        } else if (i == *at && parts.size() == longest) {
          named.insert(category);
        }
        break;
      }
    }
    if (named.size() == 1) return *named.begin();
    if (named.size() > 1) return std::nullopt;
  }
  // "the teddy" for the teddy bear: a word WordNet puts in one synset with
  // a kind's name, when it names one kind here.
  std::set<std::string> named;
  for (const std::string& w : words) {
    if (is_determiner(w) || w.size() < 3) continue;
    const std::vector<std::string> same = lexicon.synonyms(w);
    for (ObjectId o : world.universe->of_kind(ObjectKind::kItem))
      if (std::find(same.begin(), same.end(), spoken_category(world.universe->info(o).category)) != same.end())
        named.insert(world.universe->info(o).category);
    if (!named.empty()) break;
  }
  if (named.size() == 1) return *named.begin();
  return std::nullopt;
}

// The words without each "not in ...", "not on ..." to the end of its
// clause: "the magazine goes on the shelf not in the recycling bin, i
// haven't read it" -> "the magazine goes on the shelf, i haven't read it".
std::vector<std::string> without_places_said_not(const std::vector<std::string>& words) {
  std::vector<std::string> kept;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (words[i] == "not" && i + 1 < words.size() && is_one_of(words[i + 1], {"in", "on", "into", "onto", "inside"})) {
      while (i + 1 < words.size() && words[i + 1] != ",") ++i;
      continue;
    }
    kept.push_back(words[i]);
  }
  return kept;
}

// At a question about the task's steps, a reply that says where one kind
// of thing already dealt with goes ("the notebook goes on the bookshelf",
// "put the dinosaur in the toy chest", "move the sticky note to the
// wastebasket"): that thing's goal, as a correction of where it was put. It must say so with
// a verb of placing, so that "the dishes in the sink next" stays a part.
// `dealt_with`: whether the kind must have a thing already dealt with;
// else any thing of the kind is the one read about.
std::optional<GoalGiven> goal_said_at_a_step(const Grounder& grounder, const World& world,
                                             const ReplyContext& context, std::string_view said, bool dealt_with) {
  std::vector<std::string> words = reply_words(said);
  split_hyphenated_kinds(words, *world.universe);
  // "no wait, the sketchbook should be on the shelf": the marker before a
  // correction says nothing of where the thing goes.
  std::size_t first = 0;
  while (first < words.size() && (acts::is_marker(words[first]) || acts::is_interjection(words[first]) ||
                                  is_one_of(words[first], {"no", "nope", "nah", ",", ".", "!"})))
    ++first;
  if (first == words.size()) return std::nullopt;
  words.erase(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(first));
  const std::string kept = first > 0 ? quoted_words(words) : std::string(said);
  const std::string_view text = kept;
  // ("the mug should be on the desk", "the pad should hang on the left
  // hook": "be" after a modal, and verbs of resting, place too.)
  bool placing = false;
  for (std::size_t i = 0; i < words.size(); ++i)
    placing = placing ||
              is_verb_of_going(words[i]) ||
              is_one_of(words[i], {"belonged", "put", "move", "moved", "hang", "hangs", "sit", "sits", "stay", "stays"}) ||
              (words[i] == "be" && i > 0 && is_one_of(words[i - 1], {"should", "must", "to", "can", "could", "would"}));
  if (!placing) return std::nullopt;
  std::optional<std::string> kind = the_kind_named(world, grounder.lexicon(), words);
  if (!kind) return std::nullopt;
  // A thing of that kind already dealt with: the one put somewhere the
  // teacher now corrects. (Of a kind not dealt with yet, it is a rule or
  // a place named, as the question's own reader reads it.)
  // Of several, the one whose properties the words name ("the clean
  // diapers", after the dirty one was dealt with first).
  std::optional<ObjectId> thing;
  std::size_t named_best = 0;
  for (ObjectId o : context.dealt_with) {
    if (world.universe->info(o).category != *kind) continue;
    const std::vector<std::string>& properties = world.universe->info(o).properties;
    const auto named = static_cast<std::size_t>(std::count_if(properties.begin(), properties.end(), [&](const std::string& p) {
      return std::find(words.begin(), words.end(), p) != words.end();
    }));
    if (!thing || named > named_best) {
      thing = o;
      named_best = named;
    }
  }
  if (!dealt_with)
    for (ObjectId o : world.universe->of_kind(ObjectKind::kItem))
      if (!thing && world.universe->info(o).category == *kind) thing = o;
  if (!thing) return std::nullopt;
  ReplyContext as_goal = context;
  as_goal.asked = Asked::kGoal;
  as_goal.object = thing;
  as_goal.dealt_with.clear();  // read as the thing's own goal, never as another correction
  Reply read = read_reply(grounder, world, as_goal, text);
  // "the magazine goes on the shelf not in the recycling bin": where it
  // does not go says nothing more here.
  if (std::holds_alternative<Unusable>(read))
    if (auto shorter = without_places_said_not(words); shorter.size() < words.size())
      read = read_reply(grounder, world, as_goal, quoted_words(shorter));
  // Where the thing is already, with its door said otherwise ("the hoodie
  // goes in the wardrobe, close it"): the goal, not "leave it there".
  if (const auto* left = std::get_if<Finished>(&read); left && !left->ending)
    read = read_reply_plain(grounder, world, as_goal, text);
  const auto* given = std::get_if<GoalGiven>(&read);
  if (given == nullptr) return std::nullopt;
  const std::vector<ObjectId> mentioned = given->goal.objects();
  if (std::find(mentioned.begin(), mentioned.end(), *thing) == mentioned.end()) return std::nullopt;
  return *given;
}

}  // namespace

Reply read_reply(const Grounder& grounder, const World& world, const ReplyContext& context, std::string_view text) {
  const bool step = context.asked == Asked::kTaskStep || context.asked == Asked::kSubtaskEnd;
  if (step)
    if (auto corrected = goal_said_at_a_step(grounder, world, context, text, true)) return *corrected;
  Reply reply = read_reply_plain(grounder, world, context, text);
  // Where a kind not dealt with yet goes is no part over its place ("the
  // magazine goes on the bookshelf" is not clearing the bookshelf): the
  // parts come first (a rule said so is kept by the agent).
  if (step &&
      (std::holds_alternative<SubtaskNamed>(reply) || std::holds_alternative<LoopNamed>(reply) ||
       (std::holds_alternative<Unusable>(reply) && !std::get<Unusable>(reply).topic_places.empty())) &&
      goal_said_at_a_step(grounder, world, context, text, false)) {
    std::vector<std::string> examples = example_replies(world, context);
    return Unusable{parts_come_first(examples.front()), std::move(examples), std::nullopt};
  }
  if (context.asked != Asked::kGoal) return reply;
  reply = read_goal_reply(grounder, world, context, text, std::move(reply));
  like_the_goal_referred_to(grounder, world, context, text, reply);
  // "actually the kneeling pad should hang on the left hook", asked about
  // another thing: where a thing already dealt with now goes.
  if (std::holds_alternative<Unusable>(reply) && !context.dealt_with.empty())
    if (auto corrected = goal_said_at_a_step(grounder, world, context, text, true)) return *corrected;
  return reply;
}


Reply read_reply_plain(const Grounder& grounder, const World& world, const ReplyContext& context,
                       std::string_view text) {
  if (text.size() > kMaxSentenceBytes)
    return Unusable{"That is too long for me; please say it in a shorter sentence.", example_replies(world, context),
                    std::nullopt};
  if (auto c = command(grounder, world, text)) return *c;
  std::optional<Problem> grammar_failure;
  if (auto reply = scripted(grounder, world, context, text, grammar_failure)) return *reply;
  std::vector<std::string> words = reply_words(text);
  split_hyphenated_kinds(words, *world.universe);
  join_world_names(words, *world.universe);
  if (std::all_of(words.begin(), words.end(), [](const std::string& w) { return w == ","; }))
    return Unusable{"I didn't get a reply.", example_replies(world, context), std::nullopt};
  ReplyInput in(grounder, world, context, std::move(words));
  Reply reply = Unusable{};
  switch (context.asked) {
    case Asked::kTask: reply = read_task(in); break;
    case Asked::kTaskStep:
    case Asked::kSubtaskEnd: reply = read_structure(in); break;
    case Asked::kGoal: reply = read_goal(in); break;
    case Asked::kAction: reply = read_action(in); break;
    case Asked::kYesNo: reply = read_yes_no(in); break;
    case Asked::kWhich: reply = read_which(in); break;
  }
  // Where the grammar understood the sentence and only the world refused
  // it, its reason is the more exact one.
  if (auto* failed = std::get_if<Unusable>(&reply); failed && grammar_failure && !failed->failure)
    return unusable(in, *grammar_failure);
  return reply;
}

std::vector<std::string> example_replies(const World& world, const ReplyContext& context) {
  std::string room = world.location.empty() ? "room" : world.location;
  std::replace(room.begin(), room.end(), '-', ' ');  // "exam-room" is said "exam room"
  std::vector<std::string> out;
  switch (context.asked) {
    case Asked::kTask: out = {"tidy the " + room, "I want you to tidy the " + room}; break;
    case Asked::kTaskStep: out = structure_examples(world, false); break;
    case Asked::kSubtaskEnd: out = structure_examples(world, true); break;
    case Asked::kGoal: out = goal_examples(world, context); break;
    case Asked::kAction: out = action_examples(world, context); break;
    case Asked::kYesNo: out = {"yes", "no"}; break;
    case Asked::kWhich:
      for (ObjectId id : context.choices) out.push_back(distinct_noun_for(world, id, context.choices));
      break;
  }
  return out;
}

std::string format_reply(const World& world, const Reply& reply) {
  const Universe& u = *world.universe;
  auto ids_of = [&](const std::vector<ObjectId>& ids) {
    std::vector<std::string> names;
    for (ObjectId id : ids) names.push_back(u.name(id));
    return join(names, " ");
  };
  struct Formatter {
    const World& world;
    const Universe& u;
    decltype(ids_of)& list;
    std::string operator()(const TaskNamed& r) const { return "task " + r.name; }
    std::string operator()(const SubtaskNamed& r) const {
      return "subtask " + r.verb + " " + std::string(to_string(r.relation)) + " " + list(r.places);
    }
    std::string operator()(const LoopNamed& r) const {
      return "loop " + std::string(to_string(r.relation)) + " " + list(r.places);
    }
    std::string operator()(const Finished& f) const { return f.ending ? "finished (an ending)" : "finished"; }
    std::string operator()(const Proceed&) const { return "proceed"; }
    std::string operator()(const GoalGiven& r) const {
      std::string out = "goal " + format_goal(*world.domain, u, r.goal);
      for (const Goal& g : r.others) out += "; also " + format_goal(*world.domain, u, g);
      return out;
    }
    std::string operator()(const ActionGiven& r) const {
      std::string out = "action " + format_action(*world.domain, u, r.action);
      for (const Action& a : r.more) out += ", " + format_action(*world.domain, u, a);
      return out;
    }
    std::string operator()(const YesNo& r) const {
      return std::string(r.yes ? "yes" : "no") + (r.rest.empty() ? "" : "; then: " + r.rest);
    }
    std::string operator()(const Chosen& r) const { return "chosen " + u.name(r.object); }
    std::string operator()(const Command& r) const {
      switch (r.kind) {
        case Command::Kind::kHelp: return "command help";
        case Command::Kind::kStatus: return "command status";
        case Command::Kind::kUndo: return "command undo";
        case Command::Kind::kForget: return "command forget " + r.argument;
        case Command::Kind::kQuit: return "command quit";
        case Command::Kind::kWhatsLeft: return "command whats-left";
        case Command::Kind::kWhere: return "command where " + r.argument;
        case Command::Kind::kWhy:
          return std::string(r.asking ? "command why-asking" : r.earlier ? "command why-earlier" : "command why") +
                 (r.things.empty() ? "" : " about " + list(r.things));
        case Command::Kind::kDo: {
          std::string out = "command do";
          for (const Action& a : r.actions) out += " " + format_action(*world.domain, u, a);
          if (!r.left_open.empty()) out += "; left open from now on: " + list(r.left_open);
          return out;
        }
      }
      return "command";
    }
    std::string operator()(const Ambiguous& r) const { return "ambiguous " + r.phrase + ": " + list(r.candidates); }
    std::string operator()(const Unusable& r) const {
      return "unusable" + (r.failure ? " " + std::string(to_string(r.failure->kind)) + " " + r.failure->detail : "");
    }
  };
  return std::visit(Formatter{world, u, ids_of}, reply);
}

}  // namespace apprentice::language
