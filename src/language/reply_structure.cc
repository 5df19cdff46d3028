// The task's structure in everyday English (language/reply_reading.h): its
// parts, their ends and loops. The task's name is in reply_task.cc; yes and
// no are in reply_yes_no.cc.
#include <algorithm>
#include <array>

#include "language/generation.h"
#include "language/known_verbs.h"
#include "language/narration.h"
#include "language/reply_reading.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language {

// Splits at "," only.
std::string parts_come_first(std::string_view example) {
  return "First tell me the parts of the task, such as \"" + std::string(example) +
         "\"; I will ask where each thing goes when I come to it.";
}

std::vector<std::vector<std::string>> comma_pieces(const std::vector<std::string>& words) {
  std::vector<std::vector<std::string>> out(1);
  for (const std::string& w : words) {
    if (w == ",") {
      if (!out.back().empty()) out.emplace_back();
    } else {
      out.back().push_back(w);
    }
  }
  if (out.back().empty()) out.pop_back();
  return out;
}

namespace {

using Words = std::vector<std::string>;

bool contains(const Words& words, const std::vector<std::string_view>& phrase) {
  if (phrase.empty() || words.size() < phrase.size()) return false;
  for (std::size_t i = 0; i + phrase.size() <= words.size(); ++i)
    if (std::equal(phrase.begin(), phrase.end(), words.begin() + static_cast<std::ptrdiff_t>(i))) return true;
  return false;
}

bool has_word(const Words& words, std::initializer_list<std::string_view> set) {
  return std::any_of(words.begin(), words.end(), [&](const std::string& w) { return is_one_of(w, set); });
}


// --- The structure -----------------------------------------------------------

// "done", "that is all", "we are finished", "nothing else", "that's it for
// the table".
bool finished_words(const Words& words) {
  if (has_word(words, {"done", "finished", "complete", "completed"}) && !has_word(words, {"not"})) return true;
  for (const std::vector<std::string_view>& phrase : std::vector<std::vector<std::string_view>>{
           {"that", "is", "all"}, {"that", "is", "it"}, {"that", "is", "everything"}, {"will", "be", "all"},
           {"would", "be", "all"}, {"nothing", "else"}, {"nothing", "more"}, {"no", "more"}, {"all", "set"},
           {"that", "is", "enough"}, {"that", "should", "be", "it"}, {"that", "should", "do", "it"},
           {"that", "does", "it"}, {"that", "was", "it"}, {"that", "was", "all"}, {"nothing", "left"},
           {"the", "end"}, {"are", "through"}, {"is", "clear"}, {"is", "empty"}, {"is", "clean"}, {"is", "tidy"},
           {"are", "clear"}, {"are", "empty"}, {"is", "cleared"}, {"is", "emptied"}, {"is", "tidied"},
           {"is", "cleaned"}, {"are", "cleared"}, {"is", "clear", "now"}, {"whole", "task"}, {"whole", "thing"}, {"whole", "job"},
           {"entire", "task"}, {"nothing", "to", "do"}, {"all", "clear"}, {"the", "lot"}, {"we", "are", "good"},
           {"were", "good"}})
    if (contains(words, phrase)) return true;
  return words.size() == 1 && is_one_of(words[0], {"nothing", "enough", "stop"});
}

// Asked whether there is more to a part: "there's loads more", "still the
// twine", "there are still bandages on there", said without a "no".
bool says_there_is_more(const Words& words) {
  return has_word(words, {"more", "still"}) && !has_word(words, {"no", "not", "nothing", "any"});
}

bool proceed_words(const Words& words) {
  if (has_word(words, {"next", "continue", "proceed", "repeat", "again", "rest", "others", "other", "remaining",
                       "onward", "onwards"}))
    return true;
  for (const std::vector<std::string_view>& phrase : std::vector<std::vector<std::string_view>>{
           {"keep", "going"}, {"keep", "on"}, {"go", "on"}, {"carry", "on"}, {"move", "on"}, {"keep", "at", "it"}, {"go", "ahead"},
           {"keep", "it", "up"}, {"same", "way"}, {"the", "same"}, {"same", "for"}, {"same", "with"},
           {"all", "of", "them"}, {"one", "more"}, {"not", "yet"}, {"not", "done"}, {"not", "finished"},
           {"there", "is", "more"}})
    if (contains(words, phrase)) return true;
  // "keep clearing", "continue unloading": more of the part under way.
  for (std::size_t i = 0; i + 1 < words.size(); ++i)
    if (is_one_of(words[i], {"keep", "continue", "go", "carry"}) && words[i + 1].size() > 5 &&
        words[i + 1].ends_with("ing"))
      return true;
  return words.size() == 1 && is_one_of(words[0], {"more", "go", "same"});
}

// "The first thing is to clear the table", "the last step is unloading
// the dish rack", "next up is storing ...": a copula after words that only
// say where in the sequence a part comes. The words after it, or nullopt
// when the reply has no such frame.
std::optional<Words> after_sequence_frame(const Words& words) {
  bool sequence_noun = false;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::string& w = words[i];
    if (is_one_of(w, {"thing", "step", "part", "stage", "task", "job", "bit", "subtask", "one", "up"})) {
      sequence_noun = true;
      continue;
    }
    if (is_copula(w) || w == ",") {
      if (!sequence_noun || i + 1 >= words.size()) return std::nullopt;
      std::size_t from = i + 1;
      while (from < words.size() && is_one_of(words[from], {"to", "that", "we", "you", ","})) ++from;
      if (from >= words.size()) return std::nullopt;
      return Words(words.begin() + static_cast<std::ptrdiff_t>(from), words.end());
    }
    if (!is_determiner(w) && !ordinal(w) &&
        !is_one_of(w, {"first", "next", "last", "final", "then", "and", "after", "that", "our", "your", "my",
                       "second", "third", "fourth", "very", "main", "other"}))
      return std::nullopt;
  }
  return std::nullopt;
}

// Whether the reply asks for a loop: "repeat this for everything on the
// table", "keep doing that until the table is empty", "do this for every
// object on the table".
bool loop_words(const Words& words) {
  bool verb = has_word(words, {"repeat", "keep", "do", "continue", "loop", "iterate"});
  bool cue = has_word(words, {"while", "until", "till"}) || contains(words, {"as", "long", "as"}) ||
             contains(words, {"for", "every"}) || contains(words, {"for", "each"}) || contains(words, {"for", "all"}) ||
             contains(words, {"for", "everything"}) || contains(words, {"for", "anything"});
  return (verb && cue) || (!words.empty() && words[0] == "repeat" && words.size() > 1);
}

struct Places {
  std::vector<ObjectId> objects;
  std::string phrase;
};

class StructureReader {
 public:
  explicit StructureReader(const ReplyInput& in) : in_(in), resolver_(in) {}

  Reply read() {
    Words words = without_fillers(in_.words, in_.vocabulary);
    if (loop_words(in_.words)) {
      auto places = first_places(read_clauses(in_.words, in_.vocabulary));
      if (places) return LoopNamed{relation(places->objects.front()), places->objects};
      if (problem_) return outcome();
    }
    std::vector<Clause> clauses = read_clauses(in_.words, in_.vocabulary);
    // "the piano's covered in stuff. clear it off": "it" in a later clause
    // is the place an earlier one named.
    if (clauses.size() > 1) {
      const Findings before = findings();
      if (auto named = first_places(clauses)) named_before_ = named->objects;
      restore(before);
    }
    for (std::size_t i = 0; i < clauses.size(); ++i) {
      if (auto subtask = read_subtask(clauses[i])) {
        if (names_a_step(*subtask)) return *subtask;
        // "the piano's covered in stuff. clear it off": a verb that names
        // no step ("cover") gives way to a later one that does.
        if (auto later = later_step(clauses, i + 1)) return *later;
        return *subtask;
      }
      if (problem_ || ambiguous_) break;
    }
    if (!problem_ && !ambiguous_ && !item_named_)
      if (auto subtask = across_clauses(clauses)) return *subtask;
    bool finished = false, proceed = false;
    for (const Words& piece : comma_pieces(in_.words)) {
      Words kept = without_fillers(piece, in_.vocabulary);
      if (finished_words(kept)) finished = true;
      else if (proceed_words(piece) || (in_.context.asked == Asked::kSubtaskEnd && says_there_is_more(piece)))
        proceed = true;
    }
    if (finished) {
      // "that's it for the table", "the counter is clear", asked for the
      // task's next step: that part is over, which says nothing of the
      // task; asked back rather than ending the task with parts left.
      if (in_.context.asked == Asked::kTaskStep && !problem_ && !ambiguous_)
        if (auto part = first_places(clauses); part && !part->objects.empty())
          return unusable(in_, Problem{"So " + spoken_places(in_.world, part->objects) +
                                           " is done. Say \"that's all\" if the whole task is done, or tell me what "
                                           "to do next.",
                                       std::nullopt});
      return Finished{};
    }
    // "the counter next", "same with the counter": the last subtask's verb
    // at a place named without one, when it is the verb for places of this
    // kind ("clear" a surface, "empty" a receptacle). "Sort the baskets",
    // then "now the folding table", is asked back: sorting a table, or
    // clearing a bucket, may not be what was meant.
    std::optional<Places> named;
    if (!problem_ && !ambiguous_ && !item_named_) named = first_places(clauses);
    // (Not where a verb of placing or going says a thing goes: "the leash
    // goes on the bottom hook" is no part over the hook rack.)
    if (named && !in_.context.taught_subtasks.empty() && !says_where_a_thing_goes(clauses)) {
      std::vector<ObjectId> holding = holding_items(named->objects);
      const std::string& last = in_.context.taught_subtasks.back();
      if (!holding.empty() && last == clearing_verb(in_.world.universe->info(holding.front()).kind))
        return SubtaskNamed{last, relation(holding.front()), holding};
    }
    // "start with the table", "the sink first", before any part was taught:
    // the verb for places of its kind, said in the read-back.
    // (A surface is cleared; what is done with a receptacle's things,
    // emptied, unloaded or sorted, is asked, as is a place of several.)
    // (Said with more, "the bench, then the floor", where "the bench" names
    // nothing here, the part is asked, lest one be lost.)
    const bool asks = !in_.words.empty() && is_one_of(in_.words.front(), {"what", "where", "which", "why", "how", "is", "are"});
    // ("start with the coffee table, theres a bunch of junk on it": what
    // the place is like, said after it, is no other part.)
    std::vector<Words> pieces;
    for (const Words& piece : comma_pieces(in_.words)) {
      const bool describes = !pieces.empty() && !piece.empty() &&
                             is_one_of(piece.front(), {"theres", "there's", "its", "it's", "thats", "that's", "there"}) &&
                             std::none_of(piece.begin(), piece.end(), [](const std::string& w) {
                               return is_one_of(w, {"then", "next"});
                             });
      if (!describes) pieces.push_back(piece);
    }
    const bool one_phrase = pieces.size() == 1 &&
                            std::none_of(pieces.front().begin(), pieces.front().end(), [](const std::string& w) {
                              return is_one_of(w, {"and", "then", "after", "before"});
                            });
    if (named && in_.context.taught_subtasks.empty() && in_.context.asked == Asked::kTaskStep && !problem_ &&
        !ambiguous_ && !item_named_ && !proceed && !asks && one_phrase) {
      std::vector<ObjectId> holding = holding_items(named->objects);
      if (holding.size() == 1 && in_.world.universe->info(holding.front()).kind == ObjectKind::kSurface) {
        const std::string verb = clearing_verb(in_.world.universe->info(holding.front()).kind);
        const std::string place = holding.size() == 1 ? distinct_noun_for(in_.world, holding.front())
                                                      : spoken_places(in_.world, holding);
        return SubtaskNamed{verb, relation(holding.front()), holding,
                            "I took " + apprentice::quoted(quoted_words(in_.words)) + " as " + ing_form(verb) + " " +
                                place + "."};
      }
    }
    if (proceed && !named) return Proceed{};
    if (problem_ || ambiguous_) return outcome();
    if (in_.context.asked == Asked::kSubtaskEnd && answer_prefix(in_.words))
      return unusable(in_, Problem{"Please say it in words: \"that's all\" if this part is done, or \"keep going\" "
                                   "if there is more to it.",
                                   std::nullopt});
    if (item_named_)
      return unusable(in_, Problem{parts_come_first(first_example()), std::nullopt});
    // A place and no verb: "the table first".
    if (named) {
      // Its own example first: the generic ones may name other places. Of
      // several places of one kind ("the buckets"), those holding things.
      std::vector<ObjectId> topic = holding_items(named->objects);
      if (topic.empty())  // "the hammer goes in the top drawer": where things go, not a part of the task
        return unusable(in_, Problem{"There is nothing " +
                                         std::string(relation(named->objects.front()) == Relation::kOn ? "on " : "in ") +
                                         spoken_places(in_.world, named->objects) +
                                         " now. " + parts_come_first(first_example()),
                                     std::nullopt});
      std::string place = topic.size() == 1 ? distinct_noun_for(in_.world, topic.front())
                                            : spoken_places(in_.world, topic);
      Unusable which = unusable(in_, Problem{"What should I do with the things " +
                                                 std::string(relation(topic.front()) == Relation::kOn ? "on " : "in ") +
                                                 place + "?",
                                             std::nullopt});
      std::erase(which.examples, "clear " + place);
      which.examples.insert(which.examples.begin(), "clear " + place);
      if (which.examples.size() > 2) which.examples.resize(2);
      which.topic_places = topic;
      return which;
    }
    return unusable(in_, Problem{"I didn't catch what comes next in the task in \"" + quoted_words(in_.words) + "\".",
                                 std::nullopt});
  }

 private:
  Reply outcome() {
    if (ambiguous_) return *ambiguous_;
    return unusable(in_, *problem_);
  }

  std::string first_example() const {
    std::vector<std::string> examples = example_replies(in_.world, in_.context);
    return examples.empty() ? "clear the table" : examples.front();
  }

  Relation relation(ObjectId place) const {
    return in_.world.universe->info(place).kind == ObjectKind::kSurface ? Relation::kOn : Relation::kIn;
  }

  bool holds_items(ObjectId place) const {
    for (PredicateId relation : {in_.world.vocabulary.on, in_.world.vocabulary.in})
      if (!in_.world.state.facts_with_second(relation, 2, place).empty()) return true;
    return false;
  }

  std::vector<ObjectId> holding_items(const std::vector<ObjectId>& places) const {
    std::vector<ObjectId> holding;
    for (ObjectId id : places)
      if (holds_items(id)) holding.push_back(id);
    return holding;
  }

  // The verb a subtask is named by: "do" after others were taught ("then
  // do the counter") is the last one's.
  std::string subtask_verb(const Clause& c) const {
    if (c.verb == "do" && !in_.context.taught_subtasks.empty()) return in_.context.taught_subtasks.back();
    return verb_name(c.verb, c.particle);
  }
  // The part of the task a clause names over the places holding things.
  // A verb that only takes things from a place ("get everything off the
  // bench", "pick up all the stuff on the floor", "take everything out of
  // the baskets") or says nothing of what to do ("do the yellow bucket")
  // names the part by the place: a surface is cleared, a receptacle
  // emptied. Another verb than the agent's step verbs ("unpack the bags")
  // is the one WordNet puts closest, with a note for the read-back
  // (known_verbs.h); else it is kept as said.
  SubtaskNamed subtask(const Clause& said, const std::vector<ObjectId>& holding) const {
    const ObjectKind kind = in_.world.universe->info(holding.front()).kind;
    // "sort out the bookshelf": "out" at a surface adds nothing to the verb.
    Clause c = said;
    if (c.particle == "out" && kind != ObjectKind::kReceptacle) c.particle.clear();
    SubtaskNamed named{subtask_verb(c), relation(holding.front()), holding};
    // "tip out the bucket", "turn out the bag", "dump out the box": a verb
    // with "out" at a receptacle takes what is in it out.
    const bool takes = c.verb_class() == VerbClass::kPick ||
                       (c.particle == "out" && kind == ObjectKind::kReceptacle && c.verb != "do");
    if (takes || is_one_of(named.verb, {"do", "get out", "take out", "get off", "take off"})) {
      std::string said = verb_name(c.verb, c.particle);
      if (c.verb != "do" && !is_one_of(said, {"get", "take", "grab", "get out", "take out", "get off", "take off"}))
        named.note = "I took " + apprentice::quoted(c.particle.empty() ? c.verb : c.verb + " " + c.particle) + " as " +
                     ing_form(clearing_verb(kind)) + ".";
      named.verb = clearing_verb(kind);
    } else if (named.verb != "do" && c.verb != "do") {
      if (auto taken = known_step_verb(in_.grounder.lexicon(), c.verb, c.particle, kind, in_.context.taught_subtasks)) {
        named.verb = taken->verb;
        named.note = taken->note;
      }
    }
    return named;
  }

  // Whether a clause's verb names a step at `place`: none said ("the
  // shelf next"), a step verb or one taught, a task's verb ("tidy it
  // up"), or a verb near a step verb.
  bool names_a_step_at(const Clause& c, ObjectId place) const {
    if (c.verb.empty() || c.verb_class() == VerbClass::kPick) return true;
    const std::string said = c.particle.empty() ? c.verb : c.verb + " " + c.particle;
    const std::span<const std::string> taught = in_.context.taught_subtasks;
    if (is_step_verb(said, taught) || is_step_verb(c.verb, taught)) return true;
    if (names_a_known_task(in_.grounder.lexicon(), c.verb, c.particle)) return true;
    return known_step_verb(in_.grounder.lexicon(), c.verb, c.particle, in_.world.universe->info(place).kind, taught)
        .has_value();
  }

  // The places a phrase names: one, or every place of one kind ("the bags").
  std::optional<Places> places(const Chunk& chunk) {
    auto found = resolver_.candidates(chunk, Role::kPlace);
    if (auto* problem = std::get_if<Problem>(&found)) {
      if (!problem_) problem_ = *problem;
      return std::nullopt;
    }
    std::vector<ObjectId> objects;
    for (ObjectId id : std::get<std::vector<ObjectId>>(found))
      if (in_.world.universe->info(id).kind != ObjectKind::kItem) objects.push_back(id);
    if (objects.empty()) return std::nullopt;
    const Universe& u = *in_.world.universe;
    bool one_kind = std::all_of(objects.begin(), objects.end(),
                                [&](ObjectId id) { return u.info(id).category == u.info(objects.front()).category; });
    if (!one_kind) {
      ambiguous_ = Ambiguous{chunk.text(), objects, say_which_question(in_.world, objects)};
      return std::nullopt;
    }
    return Places{objects, chunk.text()};
  }

  std::optional<Places> location_places(const Chunk& chunk) {
    if (!chunk.located_by || chunk.location.empty()) return std::nullopt;
    return places(Chunk::of_words(chunk.location));
  }

  // A phrase that names something in particular: not "it", not "the things".
  static bool specific(const Chunk& chunk) {
    return !chunk.pronoun && !chunk.place_pronoun && !chunk.words.empty() &&
           !std::all_of(chunk.words.begin(), chunk.words.end(), [](const std::string& w) { return is_generic_noun(w); });
  }

  // The first places a reply names, for a loop.
  std::optional<Places> first_places(const std::vector<Clause>& clauses) {
    for (const Clause& c : clauses) {
      std::vector<const Chunk*> chunks;
      if (c.subject) chunks.push_back(&*c.subject);
      if (c.object) chunks.push_back(&*c.object);
      for (const Chunk& other : c.others) chunks.push_back(&other);
      for (const Chunk* chunk : chunks) {
        if (auto found = location_places(*chunk)) return found;
        if (specific(*chunk) &&
            (in_.vocabulary.is_name_word(chunk->words.back()) || names_a_place_by_synonym(chunk->words.back())))
          if (auto found = places(*chunk)) return found;
      }
      for (const PrepPhrase& p : c.phrases) {
        if (auto found = location_places(p.noun)) return found;
        if (specific(p.noun))
          if (auto found = places(p.noun)) return found;
      }
    }
    return std::nullopt;
  }

  // "now the couch", of a sofa: a word WordNet puts in one synset with a
  // place's name.
  bool names_a_place_by_synonym(const std::string& word) const {
    const std::vector<std::string> same = in_.grounder.lexicon().synonyms(word);
    if (same.empty()) return false;
    for (const ObjectInfo& o : in_.world.universe->objects())
      if (o.kind != ObjectKind::kItem && std::find(same.begin(), same.end(), spoken_category(o.category)) != same.end())
        return true;
    return false;
  }

  static bool says_where_a_thing_goes(const std::vector<Clause>& clauses) {
    return std::any_of(clauses.begin(), clauses.end(), [](const Clause& c) {
      // ("cleaning stuff goes in the cabinet": the verb of going, not the
      // first verb, says what the clause is.)
      const bool placing = c.verb_class() == VerbClass::kBe || c.verb_class() == VerbClass::kPlace ||
                           std::any_of(c.words.begin(), c.words.end(), [](const std::string& w) { return is_verb_of_going(w); });
      return placing && std::any_of(c.phrases.begin(), c.phrases.end(), [](const PrepPhrase& p) {
               return p.preposition == Preposition::kIn || p.preposition == Preposition::kOn ||
                      p.preposition == Preposition::kTo;
             });
    });
  }

  static bool has_place_pronoun(const Clause& c) {
    auto there = [](const std::optional<Chunk>& chunk) { return chunk && chunk->place_pronoun; };
    return there(c.subject) || there(c.object) ||
           std::any_of(c.others.begin(), c.others.end(), [](const Chunk& o) { return o.place_pronoun; }) ||
           std::any_of(c.phrases.begin(), c.phrases.end(), [](const PrepPhrase& p) { return p.noun.place_pronoun; });
  }

  // The places named last before clause `k`, for "there".
  std::optional<Places> last_places(const std::vector<Clause>& clauses, std::size_t k) {
    for (std::size_t at = k; at-- > 0;)
      if (auto found = first_places({clauses[at]})) return found;
    return std::nullopt;
  }

  // "go through the dish rack and put everything away": the verb in one
  // clause, over everything, and the place in another.
  std::optional<Reply> across_clauses(const std::vector<Clause>& clauses) {
    for (std::size_t k = 0; k < clauses.size(); ++k) {
      const Clause& c = clauses[k];
      if (names_no_subtask(c) || c.verb == "do") continue;
      if (c.verb_class() == VerbClass::kOpen || c.verb_class() == VerbClass::kClose) continue;
      if (c.object && specific(*c.object)) continue;
      // The place nearest the verb: its own clause ("store the things
      // there": the place named just before), then the ones before it,
      // then after.
      std::optional<Places> found;
      for (std::size_t d = 0; !found && !problem_ && !ambiguous_ && d < 2 * clauses.size(); ++d) {
        std::size_t at = d <= k ? k - d : d;
        if (d > k && at >= clauses.size()) break;
        if (at == k && d > 0) continue;
        found = first_places({clauses[at]});
        if (!found && at == k && k > 0 && has_place_pronoun(c)) found = last_places(clauses, k);
      }
      if (!found || problem_ || ambiguous_) return std::nullopt;
      std::vector<ObjectId> holding = holding_items(found->objects);
      if (holding.empty()) return std::nullopt;
      // A verb said apart from its place names a part when it is a step
      // verb, or is done to what is there ("now the counter, put all that
      // stuff away"): "wait" in "oh wait, the magazine goes on the shelf"
      // is none.
      SubtaskNamed named = subtask(c, holding);
      const bool over_the_things = c.object && (c.object->pronoun || !specific(*c.object));
      if (!names_a_step(named) && !over_the_things) return std::nullopt;
      return named;
    }
    return std::nullopt;
  }

  // "clear the table", "store the things on the counter", "put the stuff on
  // the counter away", "the dishes in the dish rack need to be unloaded".
  // Verbs that say when or how, not what: no subtask is named by them.
  // Nor verbs that say where things go ("the magazine goes on the shelf"),
  // what not to do ("leave", "forget"), or what the teacher thinks, and
  // "I'm done", which ends.
  static bool names_no_subtask(const Clause& c) {
    // ("put them in the bottom drawer" puts things somewhere; "put away the
    // toys" may be a part.)
    // ("cleaning stuff goes in the cabinet": a verb's -ing form before a
    // verb of going names the things that go, as "cleaning supplies" does.)
    const auto verb_at = std::find(c.words.begin(), c.words.end(), c.verb_word);
    const bool names_things_that_go =
        c.verb_word.ends_with("ing") && verb_at != c.words.end() &&
        std::any_of(verb_at + 1, c.words.end(), [](const std::string& w) { return is_verb_of_going(w); });
    return c.verb.empty() || c.adjective() || c.verb_class() == VerbClass::kBe || (c.copula && c.verb_word == "done") ||
           (c.verb == "put" && c.particle.empty()) || names_things_that_go ||
           is_one_of(c.verb, {"be", "repeat", "keep", "continue", "go", "finish", "end", "stop", "start", "begin",
                              "move", "come", "think", "know", "want", "need", "let", "say", "mean", "see", "look",
                              "leave", "forget", "wait", "belong", "thank", "hate", "like", "love", "read", "tell",
                              "ask", "mind", "hold", "guess", "wish", "hope", "forgive", "remember", "recall",
                              "notice"});
  }

  // Whether a part of the task read is said with a step verb the agent
  // knows, or one the teacher taught before.
  bool names_a_step(const Reply& reply) const {
    const auto* part = std::get_if<SubtaskNamed>(&reply);
    if (part == nullptr) return true;
    return is_step_verb(part->verb, in_.context.taught_subtasks);
  }

  // The first part said with a known step verb in clauses[from...]; what
  // the reading of the others found wrong is forgotten.
  std::optional<Reply> later_step(const std::vector<Clause>& clauses, std::size_t from) {
    const Findings before = findings();
    for (std::size_t k = from; k < clauses.size(); ++k)
      if (auto subtask = read_subtask(clauses[k]); subtask && names_a_step(*subtask)) return subtask;
    restore(before);
    return std::nullopt;
  }

  // What reading clauses found wrong so far, to look ahead and forget what
  // the look found.
  struct Findings {
    std::optional<Problem> problem;
    std::optional<Ambiguous> ambiguous;
    bool item_named = false;
  };
  Findings findings() const { return {problem_, ambiguous_, item_named_}; }
  void restore(const Findings& before) {
    problem_ = before.problem;
    ambiguous_ = before.ambiguous;
    item_named_ = before.item_named;
  }

  std::optional<Reply> read_subtask(const Clause& c) {
    if (names_no_subtask(c)) return std::nullopt;
    if (c.verb_class() == VerbClass::kOpen || c.verb_class() == VerbClass::kClose) return std::nullopt;
    std::optional<Places> found;
    for (const std::optional<Chunk>* chunk : {&c.object, &c.subject})
      if (!found && *chunk && specific(Chunk::of_words((*chunk)->location))) found = location_places(**chunk);
    // The object unresolved ("the crumbs") may only describe what is at a
    // place named after it; then it is no problem.
    std::optional<Problem> unresolved;
    if (!found && c.object && specific(*c.object)) {
      auto objects = resolver_.candidates(*c.object, Role::kPlace);
      auto* ids = std::get_if<std::vector<ObjectId>>(&objects);
      bool place = ids && std::any_of(ids->begin(), ids->end(), [&](ObjectId id) {
                     return in_.world.universe->info(id).kind != ObjectKind::kItem;
                   });
      if (place) {
        found = places(*c.object);
      } else if (ids) {
        item_named_ = true;  // a particular thing: a goal or an action, not a part of the task
        return std::nullopt;
      } else {
        unresolved = std::get<Problem>(objects);
      }
    }
    if (!found) {
      for (const PrepPhrase& p : c.phrases) {
        if (!specific(p.noun) || p.preposition == Preposition::kTo) continue;
        if (auto candidate = places(p.noun)) {
          found = candidate;
          break;
        }
      }
    }
    // "clear it", or "clear" alone, after "What should I do with the things
    // on the coffee table?".
    // Or after a clause that named the place ("the piano's covered in
    // stuff. clear it off").
    bool about_it = !c.object || c.object->pronoun || c.object->place_pronoun;
    const bool pronoun = c.object && (c.object->pronoun || c.object->place_pronoun);
    static const std::vector<ObjectId> kNone;
    const std::vector<ObjectId>& topic = !in_.context.topic_places.empty() ? in_.context.topic_places
                                         : pronoun                         ? named_before_
                                                                           : kNone;
    // A verb of its own there names a part only if it is a step verb, or
    // near one, or one taught: "ok cool thats all" after "What should I do
    // with the things in the tub?" is no cooling of the tub.
    if (!found && (!unresolved || pronoun) && about_it && c.phrases.empty() && !topic.empty() &&
        names_a_step_at(c, topic.front())) {
      found = Places{topic, "it"};
      unresolved.reset();
    }
    if (!found && unresolved && !problem_) problem_ = unresolved;
    if (!found || problem_ || ambiguous_) return std::nullopt;
    std::vector<ObjectId> holding = holding_items(found->objects);
    if (holding.empty()) {
      item_named_ = true;  // a place where things go, not where they are
      return std::nullopt;
    }
    return subtask(c, holding);
  }

  const ReplyInput& in_;
  Resolver resolver_;
  std::optional<Problem> problem_;
  std::optional<Ambiguous> ambiguous_;
  bool item_named_ = false;
  // The places of a part read from an earlier clause, for "it" in a later one.
  std::vector<ObjectId> named_before_;
};


}  // namespace

Reply read_structure(const ReplyInput& in) {
  if (auto rest = after_sequence_frame(in.words)) {
    ReplyInput inner(in.grounder, in.world, in.context, std::move(*rest));
    return StructureReader(inner).read();
  }
  return StructureReader(in).read();
}

bool says_finished(const std::vector<std::string>& words, const ReplyInput& in) {
  return finished_words(without_fillers(words, in.vocabulary));
}

bool says_only_an_ending(const std::vector<std::string>& words, const ReplyInput& in) {
  // Clauses break at "," and at the words that join clauses; each must end
  // something, or leave things ("leave the rest"), or be fillers.
  std::vector<Words> clauses(1);
  for (const std::string& w : words) {
    if (is_one_of(w, {",", "and", "then", "but", "so"})) {
      if (!clauses.back().empty()) clauses.emplace_back();
    } else {
      clauses.back().push_back(w);
    }
  }
  bool ends = false;
  for (const Words& clause : clauses) {
    Words kept = without_fillers(clause, in.vocabulary);
    if (kept.empty()) continue;
    if (finished_words(kept)) ends = true;
    else if (!is_one_of(kept.front(), {"leave", "skip"})) return false;
  }
  return ends;
}

}  // namespace apprentice::language
