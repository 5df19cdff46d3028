// A reply as dialogue acts (language/reply.h, read_acts): whatever the
// question, a reply may take back the last one ("oops scratch that"),
// correct it ("no wait, the bottom drawer": an undo and the answer the
// undone question should have had), ask something ("what's left?", "where
// is the soap?", "why did you close it?"), ask for a one-off action ("oh
// and close the top drawer"), or hold words that carry nothing here
// ("nah", "lol", "it's soaking"); the rest is the answer, read by the
// question's own reader (read_reply).
//
// The reply is cut at sentence and clause punctuation into segments. Each
// segment is one of: fillers only; an undo; a correction's marker ("no
// wait", "oops", "I meant"); a question of the teacher's; a one-off door
// action; or part of the answer. A door action is part of a goal when it
// is about the goal's own place ("in the hamper, close the lid").
#include <algorithm>

#include "language/generation.h"
#include "language/narration.h"
#include "language/parser.h"
#include "language/reply_reading.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language {
namespace {

using Words = std::vector<std::string>;

// Words that only set the tone: "um", "ugh", "lol", "ok so", "oh and".
bool is_interjection(std::string_view w) {
  return is_one_of(w, {"um", "umm", "ummm", "uh", "uhh", "er", "erm", "ugh", "hmm", "hmmm", "hm", "ok", "so", "oh",
                       "lol", "haha", "well", "hey", "hi", "hiya", "hello", "btw", "alright", "and", "also", "plus",
                       "please", "right", "anyway", "yeah", "ah", "aha", "ooh", "argh", "gosh", "jeez", "omg", "idk",
                       "lemme", "see", "thanks", "thank", "you", "cheers", "sorry", "mate", "buddy", "kk"});
}

// The words of a correction's marker: "no wait", "oops", "nah", "wait what".
bool is_marker(std::string_view w) {
  return is_one_of(w, {"no", "nah", "nope", "wait", "oops", "whoops", "actually", "sorry", "what", "oh", "ugh",
                       "hmm", "um"});
}

struct Segment {
  std::string text;  // as typed
  Words words;       // reply_words
};

// The reply cut at , ; : . ! ? and free-standing dashes.
std::vector<Segment> segments(std::string_view text) {
  std::vector<Segment> out;
  std::string current;
  auto flush = [&] {
    Words words = reply_words(current);
    std::erase(words, std::string(","));
    if (!words.empty()) out.push_back({std::string(trim(current)), std::move(words)});
    current.clear();
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    bool dash = c == '-' && (i == 0 || text[i - 1] == ' ') && (i + 1 >= text.size() || text[i + 1] == ' ');
    if (c == ',' || c == ';' || c == ':' || c == '.' || c == '!' || c == '?' || dash) flush();
    else current.push_back(c);
  }
  flush();
  return out;
}

Words without_interjections(Words words) {
  while (!words.empty() && is_interjection(words.front())) words.erase(words.begin());
  return words;
}

bool has(const Words& words, std::initializer_list<std::string_view> phrase) {
  return std::search(words.begin(), words.end(), phrase.begin(), phrase.end()) != words.end();
}

// "undo", "scratch that", "go back one", "that was wrong": how many undos
// (0: not an undo).
int undos(const Words& said) {
  Words words;
  for (const std::string& w : said)
    if (!is_marker(w) && !is_interjection(w)) words.push_back(w);
  if (words.empty()) return 0;
  bool all = std::all_of(words.begin(), words.end(), [](const std::string& w) {
    return is_one_of(w, {"undo", "scratch", "that", "take", "back", "go", "one", "was", "is", "wrong", "the", "last",
                         "it", "not", "right", "mistake", "my", "bad", "step", "answer", "revert"});
  });
  if (!all) return 0;
  if (!(has(words, {"undo"}) || has(words, {"scratch", "that"}) || has(words, {"take", "that", "back"}) ||
        has(words, {"go", "back"}) || has(words, {"wrong"}) || has(words, {"mistake"}) || has(words, {"revert"})))
    return 0;
  return std::max<int>(1, static_cast<int>(std::count(words.begin(), words.end(), "undo")));
}

// Leading marker words of a correction, and whether they are strong ("no
// wait", "oops", "I meant") or could be a filler ("nah", "no").
struct Marker {
  std::size_t length = 0;
  bool strong = false;
};
Marker marker(const Words& words) {
  Marker m;
  int noes = 0;
  while (m.length < words.size() && (is_marker(words[m.length]) || is_interjection(words[m.length]))) {
    const std::string& w = words[m.length];
    if (is_one_of(w, {"wait", "oops", "whoops", "actually", "sorry"})) m.strong = true;
    if (is_one_of(w, {"no", "nah", "nope"})) ++noes;
    ++m.length;
  }
  if (noes >= 2) m.strong = true;
  if (m.length + 1 < words.size() && words[m.length] == "i" && is_one_of(words[m.length + 1], {"meant", "mean"})) {
    m.length += 2;
    m.strong = true;
  }
  if (noes == 0 && !m.strong) m.length = 0;  // interjections alone are no marker
  return m;
}

// "what's left?", "how many things are left on the table?", "is anything
// still in the bags?", "where's the soap?", "why did you close it?".
std::optional<Command> question(const Grounder& grounder, const World& world, const Words& said) {
  Words words = said;
  while (!words.empty() && (is_interjection(words.front()) || is_marker(words.front())) && words.front() != "what")
    words.erase(words.begin());
  if (words.empty()) return std::nullopt;
  const std::string& first = words.front();
  if (first == "why") return Command{Command::Kind::kWhy, "", {}, {}};
  if (first == "where" && words.size() > 1 &&
      is_one_of(words[1], {"is", "are", "did", "does", "do", "has", "have", "was", "were"})) {
    Words thing;
    for (std::size_t i = 2; i < words.size(); ++i)
      if (!is_one_of(words[i], {"you", "it", "go", "put", "gone", "now", "end", "up", "the", "my", "other", "did"}))
        thing.push_back(words[i]);
    if (thing.empty()) return std::nullopt;
    std::string phrase = join(thing, " ");
    ReferenceContext context{world, grounder.lexicon(), std::nullopt};
    context.partial_names = true;
    auto found = candidates_for(NounPhrase{"", thing}, Role::kItem, context);
    std::vector<ObjectId> named;
    if (const auto* set = std::get_if<CandidateSet>(&found)) named = set->objects;
    return Command{Command::Kind::kWhere, phrase, named, {}};
  }
  // "what have we done so far?", "how far are we?": where the teaching is.
  if (is_one_of(first, {"what", "how", "whats"}) &&
      (has(words, {"so", "far"}) || has(words, {"how", "far"}) || has(words, {"have", "we", "done"}) ||
       has(words, {"have", "you", "done"}) || has(words, {"did", "we", "do"})))
    return Command{Command::Kind::kStatus, "", {}, {}};
  bool asks = is_one_of(first, {"what", "how", "is", "are", "anything", "any", "whats", "which"});
  bool left = has(words, {"left"}) || has(words, {"remaining"}) || has(words, {"still"}) ||
              has(words, {"else"}) || has(words, {"how", "many"}) || has(words, {"how", "much"}) ||
              (first != "what" && has(words, {"more"})) || has(words, {"is", "there"});
  // "what is left", not "what is left of the milk goes ...": no placing words.
  bool places = has(words, {"go"}) || has(words, {"goes"}) || has(words, {"put"});
  if (asks && left && !places && words.size() <= 10) return Command{Command::Kind::kWhatsLeft, "", {}, {}};
  return std::nullopt;
}

// "stop for now", "gotta go", "I'm done for today, stop": the teacher
// ends the session.
bool ends_session(const Words& said, Asked asked) {
  Words words;
  for (const std::string& w : said)
    if (!is_interjection(w) && !is_one_of(w, {"let", "us", "i", "will", "am", "we", "can", "just", "im"}))
      words.push_back(w);
  if (words.empty()) return false;
  for (std::initializer_list<std::string_view> leaving :
       {std::initializer_list<std::string_view>{"gotta", "go"}, {"gotta", "run"}, {"have", "to", "go"},
        {"got", "to", "go"}, {"need", "to", "go"}, {"have", "to", "run"}, {"call", "it", "a", "day"}})
    if (has(words, leaving)) return true;
  // "done for today" at the task's step ends the task, not the session.
  if (asked != Asked::kTaskStep && asked != Asked::kSubtaskEnd)
    for (std::initializer_list<std::string_view> done :
         {std::initializer_list<std::string_view>{"done", "for", "today"}, {"done", "for", "now"}, {"done", "for", "the", "day"}})
      if (has(words, done)) return true;
  bool stop = std::any_of(words.begin(), words.end(), [](const std::string& w) {
    return is_one_of(w, {"stop", "quit", "bye", "goodbye", "later"});
  });
  return stop && std::all_of(words.begin(), words.end(), [](const std::string& w) {
           return is_one_of(w, {"stop", "here", "for", "now", "today", "quit", "that", "is", "it", "enough", "finish",
                                "later", "continue", "bye", "goodbye", "see", "you", "the", "rest", "pause"});
         });
}

// "what can you do?", "what kinds of things can you learn?", "what do I
// type here?": the teacher asks what to say.
bool asks_for_help(const Words& said) {
  Words words = without_interjections(said);
  bool asks = std::any_of(words.begin(), words.end(), [](const std::string& w) { return is_one_of(w, {"what", "how"}); });
  if (!asks) return false;
  auto any_of = [&](std::initializer_list<std::string_view> set) {
    return std::any_of(words.begin(), words.end(), [&](const std::string& w) { return is_one_of(w, set); });
  };
  bool you_do = has(words, {"you"}) && any_of({"learn", "able"}) && any_of({"can", "could", "able", "kind", "kinds"});
  // "what can you do?", "what can you actually do?", "what are you able to do?"
  auto in_order = [&](std::initializer_list<std::string_view> seq) {
    auto at = words.begin();
    for (std::string_view w : seq) {
      at = std::find(at, words.end(), w);
      if (at == words.end()) return false;
      ++at;
    }
    return true;
  };
  bool can_you_do = in_order({"can", "you", "do"}) || in_order({"could", "you", "do"}) || has(words, {"able", "to", "do"});
  // "how does this work?", "how do I use you?": how the teaching goes.
  bool how_it_works = words.front() == "how" && any_of({"work", "works", "use", "start"});
  bool to_say = std::any_of(words.begin(), words.end(), [](const std::string& w) {
    return is_one_of(w, {"say", "type", "write", "answer"});
  });
  return (you_do || can_you_do || to_say || how_it_works) && words.size() <= 10;
}

// "close the top drawer", "shut both drawers", "open the compost bin
// first": the actions, or nullopt when the segment is not such a command.
std::optional<std::vector<Action>> door_action(const Grounder& grounder, const World& world,
                                               const ReplyContext& context, const Words& said) {
  Words words = without_interjections(said);
  while (!words.empty() && is_one_of(words.front(), {"can", "could", "would", "you", "also", "just", "then"}))
    words.erase(words.begin());
  if (words.empty() || !is_one_of(words.front(), {"close", "shut", "open"})) return std::nullopt;
  const bool open = words.front() == "open";
  Words object(words.begin() + 1, words.end());
  std::erase_if(object, [](const std::string& w) {
    return is_one_of(w, {"first", "now", "please", "too", "again", "up", "properly", "after", "afterwards"});
  });
  if (object.empty()) return std::nullopt;
  bool every = is_one_of(object.front(), {"both", "all", "every", "each"}) || object.back().ends_with("s");
  // "close it", "shut the lid": the place named last, part of an answer.
  if (!every && (is_object_pronoun(object.back()) || is_door_word(object.back()))) {
    std::size_t named = std::count_if(object.begin(), object.end(), [](const std::string& w) {
      return !is_determiner(w) && !is_object_pronoun(w) && !is_door_word(w);
    });
    if (named == 0) return std::nullopt;
  }
  ReplyContext as_action = context;
  as_action.asked = Asked::kAction;
  Reply reply = read_reply_plain(grounder, world, as_action, std::string(open ? "open " : "close ") + join(object, " "));
  if (const auto* given = std::get_if<ActionGiven>(&reply); given && given->more.empty() && !every)
    return std::vector<Action>{given->action};
  // Every place with a door the words name: "both drawers", "the lids".
  Words noun = object;
  std::erase_if(noun, [](const std::string& w) { return is_determiner(w); });
  if (noun.empty()) return std::nullopt;
  std::vector<ObjectId> places;
  bool doors = is_door_word(noun.back());
  for (ObjectId id = 0; id < world.universe->size(); ++id) {
    if (!openable(world, id)) continue;
    if (doors) {
      places.push_back(id);
      continue;
    }
    for (const std::string& form : singular_forms(noun.back()))
      if (name_parts(world.universe->info(id).category).back() == form) {
        places.push_back(id);
        break;
      }
  }
  if (places.empty()) return std::nullopt;
  std::vector<Action> actions;
  for (ObjectId id : places) {
    ActionCommand command;
    command.verb = open ? ActionVerb::kOpen : ActionVerb::kClose;
    command.object = NounPhrase{"", {world.universe->name(id)}};
    Interpretation grounded = grounder.ground(command, world, std::nullopt);
    if (grounded.ok()) actions.push_back(std::get<Action>(grounded.result));
  }
  if (actions.empty()) return std::nullopt;
  return actions;
}

bool usable(const Reply& r) { return !std::holds_alternative<Unusable>(r) && !std::holds_alternative<Ambiguous>(r); }

// The place a goal puts the thing asked about.
std::optional<ObjectId> destination(const World& world, const Reply& reply) {
  const auto* given = std::get_if<GoalGiven>(&reply);
  if (given == nullptr) return std::nullopt;
  for (const Literal& l : given->goal.literals)
    if (l.positive && l.fact.arity == 2 && (l.fact.predicate == world.vocabulary.in || l.fact.predicate == world.vocabulary.on))
      return l.fact.args[1];
  return std::nullopt;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t up = row[j];
      std::size_t swap = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      row[j] = std::min({up + 1, row[j - 1] + 1, swap});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// A word of the world's names a typed word is a slip of: "hampr" for
// "hamper", "cupbaord" for "cupboard"; "" when none or several.
std::string slip_of(const World& world, const std::string& word) {
  if (word.size() < 4) return "";
  std::string found;
  for (const ObjectInfo& info : world.universe->objects())
    for (const std::string& part : name_parts(info.category)) {
      if (part == word || part.size() < 4) continue;
      std::size_t most = word.size() >= 7 ? 2 : 1;
      // A letter swapped counts once ("cupbaord").
      std::string swapped = word;
      bool transposed = false;
      for (std::size_t i = 0; i + 1 < swapped.size() && !transposed; ++i) {
        std::swap(swapped[i], swapped[i + 1]);
        transposed = swapped == part;
        std::swap(swapped[i], swapped[i + 1]);
      }
      if (!transposed && edit_distance(word, part) > most) continue;
      if (!found.empty() && found != part) return "";
      found = part;
    }
  return found;
}

std::string quote(const std::string& s) { return "\"" + s + "\""; }

// The first word of a phrase nothing here fits that only describes ("wet",
// "dirty", "empty", "obviously"): an adjective or an "-ly" adverb to
// WordNet, no property of anything here and no part of a name here; "" when
// none.
std::string unmodelled_modifier(const Grounder& grounder, const World& world, const Words& phrase) {
  const Lexicon& lexicon = grounder.lexicon();
  if (!lexicon.has_wordnet()) return "";
  for (const std::string& w : phrase) {
    if (is_determiner(w) || w.size() < 3) continue;
    bool describes = !lexicon.adjective_lemmas(w).empty() || (w.ends_with("ly") && lexicon.knows(w));
    if (!describes) continue;
    bool here = false;
    for (const ObjectInfo& info : world.universe->objects()) {
      std::vector<std::string> parts = name_parts(info.category);
      if (std::find(info.properties.begin(), info.properties.end(), w) != info.properties.end() ||
          std::find(parts.begin(), parts.end(), w) != parts.end())
        here = true;
    }
    if (!here) return w;
  }
  return "";
}

// The answer's words read at the question; a word neither the world nor
// WordNet knows ("nah", "lol", "btw") is skipped when the rest then reads
// whole, and the notes say so. A word the meaning hangs on is not guessed
// at: "on the tabel" is asked back ("I do not know the word 'tabel'").
Reply read_answer(const Grounder& grounder, const World& world, const ReplyContext& context, std::string text,
                  std::vector<std::string>& notes) {
  const Reply first = read_reply(grounder, world, context, text);
  Reply reply = first;
  std::vector<std::string> skipped, modifiers;
  for (int tries = 0; tries < 3 && !usable(reply); ++tries) {
    const auto* u = std::get_if<Unusable>(&reply);
    if (u != nullptr && u->failure && u->failure->kind == FailureKind::kUngroundedObject) {
      // "the wet one", "the empty can", "in the trash obviously": a word
      // that describes, which the world does not model, narrows nothing.
      std::string modifier = unmodelled_modifier(grounder, world, split_words(u->failure->detail));
      Words words = reply_words(text);
      auto at = std::find(words.begin(), words.end(), modifier);
      if (modifier.empty() || at == words.end()) break;
      words.erase(at);
      modifiers.push_back(modifier);
      text = quoted_words(words);
      reply = read_reply(grounder, world, context, text);
      continue;
    }
    if (u == nullptr || !u->failure || u->failure->kind != FailureKind::kUnknownWord) break;
    const std::string word = u->failure->detail;
    Words words = reply_words(text);
    auto at = std::find(words.begin(), words.end(), word);
    if (at == words.end() || (grounder.lexicon().knows(word) && !is_interjection(word) && !is_marker(word))) break;
    if (!slip_of(world, word).empty()) break;  // a slip of a name here: the meaning hangs on it
    // A noun after a determiner ("by the thingamajig", "in the cubby") is
    // what the reply is about: the meaning hangs on it.
    if (at - words.begin() >= 2 && is_determiner(*(at - 1)) &&
        is_one_of(*(at - 2), {"in", "on", "into", "onto", "by", "near", "beside", "behind", "under", "next", "to", "at",
                              "with", "inside", "above", "below", "from"}))
      break;
    words.erase(at);
    skipped.push_back(word);
    text = quoted_words(words);
    reply = read_reply(grounder, world, context, text);
  }
  if (!usable(reply)) return first;
  for (const std::string& word : skipped) notes.push_back("I took " + quote(word) + " as a filler.");
  for (const std::string& word : modifiers)
    notes.push_back("I took " + quote(word) + " as telling nothing apart: nothing here is told apart by it.");
  return reply;
}

// Segments that name nothing here and hold no instruction ("it's
// soaking", "kids", "I need it tomorrow"): remarks.
bool is_remark(const Grounder& grounder, const World& world, const Words& words) {
  ReferenceContext context{world, grounder.lexicon(), std::nullopt};
  context.partial_names = true;
  for (const std::string& w : words) {
    if (is_determiner(w) || is_object_pronoun(w) || is_copula(w) || is_filler(w)) continue;
    if (is_one_of(w, {"in", "on", "into", "onto", "inside", "put", "go", "goes", "leave", "clear", "empty", "done", "close",
                      "shut", "open", "throw", "recycle", "take", "hang", "store", "pick", "bin", "trash",
                      "finished", "all", "next", "first", "then", "same", "too", "rest", "keep", "more"}))
      return false;
    auto found = candidates_for(NounPhrase{"", {w}}, Role::kItem, context);
    if (std::holds_alternative<CandidateSet>(found)) return false;
    auto place = candidates_for(NounPhrase{"", {w}}, Role::kPlace, context);
    if (std::holds_alternative<CandidateSet>(place)) return false;
  }
  return true;
}

std::string joined(const std::vector<const Segment*>& parts) {
  std::vector<std::string> texts;
  for (const Segment* s : parts) texts.push_back(s->text);
  return join(texts, ", ");
}

// The parts of a reply about the task's steps: cut at sentence and clause
// punctuation and at "then" ("and then", "after that"); a part's leading
// "now" or "and" is dropped. One part when there are no such cuts.
std::vector<Words> step_parts(std::string_view text) {
  std::vector<Words> parts;
  for (const Segment& s : segments(text)) {
    Words current;
    auto flush = [&] {
      while (!current.empty() && is_one_of(current.back(), {"and", "then"})) current.pop_back();
      if (current.size() > 1 && current[0] == "after" && current[1] == "that") current.erase(current.begin(), current.begin() + 2);
      while (!current.empty() && is_one_of(current.front(), {"and", "then", "now"})) current.erase(current.begin());
      if (!current.empty()) parts.push_back(current);
      current.clear();
    };
    for (std::size_t i = 0; i < s.words.size(); ++i) {
      const std::string& w = s.words[i];
      const bool after_that = w == "after" && i + 1 < s.words.size() && s.words[i + 1] == "that";
      if (w == "then" || after_that) flush();
      current.push_back(w);
    }
    flush();
  }
  return parts;
}

// "counter next", "the folding table": a place of the world said with no
// verb and nothing said of it ("the table's clear", "the bag still has
// stuff in it" say something).
bool names_a_place_alone(const Grounder& grounder, const World& world, const Words& part) {
  ReferenceContext context{world, grounder.lexicon(), std::nullopt};
  bool place = false;
  for (const std::string& w : part) {
    if (is_copula(w) || is_one_of(w, {"has", "have", "still", "more", "there", "it", "that", "this"})) return false;
    if (is_determiner(w)) continue;
    if (std::holds_alternative<CandidateSet>(candidates_for(NounPhrase{"", {w}}, Role::kPlace, context))) place = true;
  }
  return place;
}

// The verb a part begins with, as a subtask's reading took it.
bool starts_with_verb(const Words& part, const std::string& verb) {
  Words v = split_words(verb);
  return part.size() >= v.size() && std::equal(v.begin(), v.end(), part.begin());
}

// "clear the counter, then the table", "that's it for the desk, now sort
// the bookshelf", "counter next, then we're done": more than one step in
// one reply, each read whole at the question. nullopt when the reply is
// one step, or a part does not read.
std::optional<std::pair<Reply, std::vector<std::string>>> several_steps(const Grounder& grounder, const World& world,
                                                                      const ReplyContext& context,
                                                                      std::string_view text) {
  if (context.asked != Asked::kTaskStep && context.asked != Asked::kSubtaskEnd) return std::nullopt;
  std::vector<Words> parts = step_parts(text);
  if (parts.size() < 2 || parts.size() > 4) return std::nullopt;
  std::optional<Reply> first;
  std::vector<std::string> rest;
  std::string verb;  // the last verb said, for a part without one
  bool names_a_part = false;  // "that's it, we're done" is one ending
  ReplyContext at = context;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    Words part = without_interjections(parts[i]);
    if (part.empty()) return std::nullopt;
    Reply reply = read_reply(grounder, world, at, quoted_words(part));
    if (!usable(reply) && !verb.empty() && !starts_with_verb(part, verb)) {
      Words with = split_words(verb);
      with.insert(with.end(), part.begin(), part.end());
      Reply again = read_reply(grounder, world, at, quoted_words(with));
      if (usable(again)) {
        reply = again;
        part = with;
      }
    }
    // "that's it for the desk", "done with the table": an ending about
    // the part under way, said with its place.
    if (!usable(reply)) {
      auto about = std::find_if(part.begin() + 1, part.end(), [](const std::string& w) { return is_one_of(w, {"for", "with"}); });
      if (about != part.end() && about != part.begin()) {
        Reply ending = read_reply(grounder, world, at, quoted_words(Words(part.begin(), about)));
        if (std::holds_alternative<Finished>(ending)) reply = ending;
      }
    }
    const bool step = std::holds_alternative<SubtaskNamed>(reply) || std::holds_alternative<LoopNamed>(reply) ||
                      std::holds_alternative<Finished>(reply) || std::holds_alternative<Proceed>(reply);
    // "counter next, then we're done" with no verb known for "counter
    // next": acting on the ending alone would drop a part of the task, so
    // the part not understood is asked back.
    if (!step && !usable(reply) && names_a_place_alone(grounder, world, part))
      for (std::size_t j = 0; j < parts.size(); ++j) {
        if (j == i) continue;
        Reply other = read_reply(grounder, world, at, quoted_words(without_interjections(parts[j])));
        if (std::holds_alternative<Finished>(other)) return std::make_pair(reply, std::vector<std::string>{});
      }
    if (!step) return std::nullopt;
    if (const auto* named = std::get_if<SubtaskNamed>(&reply)) verb = named->verb;
    names_a_part = names_a_part || std::holds_alternative<SubtaskNamed>(reply) || std::holds_alternative<LoopNamed>(reply);
    if (i == 0) first = reply;
    else rest.push_back(quoted_words(part));
    // What follows the first part is read at the question about the task's
    // next step.
    at.asked = Asked::kTaskStep;
  }
  if (!names_a_part) return std::nullopt;
  return std::make_pair(*first, rest);
}

// "you left it open", "someone left the lid up": what a person did, told,
// not what the agent should do.
bool tells_what_someone_did(const Words& words) {
  for (std::size_t i = 1; i < words.size(); ++i)
    if (words[i] == "left" && is_one_of(words[i - 1], {"you", "someone", "somebody", "they", "he", "she", "we", "i",
                                                        "kids", "who", "guest", "guests"}))
      return true;
  return false;
}

// "there by the X", "here next to the X": a spot said by another thing.
bool there_described(const Words& words) {
  for (std::size_t i = 0; i + 1 < words.size(); ++i)
    if (is_one_of(words[i], {"there", "here"}) &&
        is_one_of(words[i + 1], {"by", "near", "next", "beside", "behind", "under", "above", "below", "between", "against"}))
      return true;
  return false;
}

// A close action for `place`, grounded; nullopt when it cannot be closed.
std::optional<Action> closing(const Grounder& grounder, const World& world, ObjectId place) {
  ActionCommand command;
  command.verb = ActionVerb::kClose;
  command.object = NounPhrase{"", {world.universe->name(place)}};
  Interpretation grounded = grounder.ground(command, world, std::nullopt);
  if (!grounded.ok()) return std::nullopt;
  return std::get<Action>(grounded.result);
}

// "the jeans go in the hamper and shut the washing machine door": a
// closing of a place no thing of the goal goes to is a one-off action, not
// part of the goal. The closings are taken out of the goal and returned.
// The script's grammar keeps its goals as they are (its sentences say
// exactly what the goal holds).
std::vector<Action> other_closings(const Grounder& grounder, const World& world, std::string_view text, Reply& reply) {
  auto* given = std::get_if<GoalGiven>(&reply);
  if (given == nullptr || parse(text).has_value()) return {};
  const Vocabulary& v = world.vocabulary;
  std::vector<ObjectId> to;
  auto collect = [&](const Goal& g) {
    for (const Literal& l : g.literals)
      if (l.positive && l.fact.arity == 2 && (l.fact.predicate == v.in || l.fact.predicate == v.on))
        to.push_back(l.fact.args[1]);
  };
  collect(given->goal);
  for (const Goal& g : given->others) collect(g);
  std::vector<ObjectId> closed;
  auto strip = [&](Goal& g) {
    std::erase_if(g.literals, [&](const Literal& l) {
      bool other = l.positive && l.fact.arity == 1 && l.fact.predicate == v.closed &&
                   std::find(to.begin(), to.end(), l.fact.args[0]) == to.end();
      if (other && std::find(closed.begin(), closed.end(), l.fact.args[0]) == closed.end()) closed.push_back(l.fact.args[0]);
      return other;
    });
  };
  strip(given->goal);
  for (Goal& g : given->others) strip(g);
  std::vector<Action> actions;
  for (ObjectId place : closed)
    if (auto a = closing(grounder, world, place)) actions.push_back(*a);
  return actions;
}

}  // namespace

ReplyActs read_acts(const Grounder& grounder, const World& world, const ReplyContext& context, std::string_view text) {
  ReplyActs out;
  Reply whole = read_reply(grounder, world, context, text);
  // A command of the whole reply, and at an action or which question the
  // question's own reading, stand as they are.
  if (std::holds_alternative<Command>(whole) || context.asked == Asked::kWhich ||
      (context.asked == Asked::kAction && usable(whole))) {
    out.acts.push_back(std::move(whole));
    return out;
  }
  if (auto steps = several_steps(grounder, world, context, text)) {
    out.acts.push_back(std::move(steps->first));
    out.then = std::move(steps->second);
    return out;
  }
  std::vector<Segment> parts = segments(text);
  std::vector<Reply> before, after;  // undos; questions and one-off actions
  std::vector<const Segment*> answer, doors;
  std::vector<std::vector<Action>> door_actions;
  std::vector<bool> door_first;  // said before the answer
  std::vector<Reply> first_doors;  // one-off actions said before the answer, done first
  // Corrections of a read-back are made at the next goal question.
  const bool corrects = context.asked == Asked::kGoal;
  Marker lead;
  bool lead_in_answer = false;
  bool weak = false;  // "nah", "no": a filler unless the answer corrects
  std::string marker_said;
  bool correcting = false;
  bool undo_words = false;  // an undo was said with the word "undo"
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Segment& s = parts[i];
    if (without_interjections(s.words).empty() && answer.empty() && before.empty()) continue;
    if (corrects && answer.empty() && before.empty()) {
      Marker m = marker(s.words);
      if (m.length > 0 && m.length >= s.words.size()) {
        correcting = correcting || m.strong;
        weak = weak || !m.strong;
        marker_said = quoted_words(s.words);
        continue;
      }
    }
    if (int n = undos(s.words); n > 0 && answer.empty()) {
      // "go back one, that was wrong": one undo; "undo undo", "undo, undo":
      // two, one per "undo" said; "wait that's wrong, undo that": one, the
      // same undo said twice.
      const bool said_undo = std::find(s.words.begin(), s.words.end(), "undo") != s.words.end();
      if (said_undo && !undo_words) before.clear();
      if (before.empty() || said_undo)
        for (int k = 0; k < n; ++k) before.push_back(Command{Command::Kind::kUndo, "", {}, {}});
      undo_words = undo_words || said_undo;
      correcting = true;
      continue;
    }
    if (ends_session(s.words, context.asked)) {
      out.acts = {Command{Command::Kind::kQuit, "", {}, {}}};
      return out;
    }
    if (asks_for_help(s.words)) {
      after.push_back(Command{Command::Kind::kHelp, "", {}, {}});
      continue;
    }
    if (auto q = question(grounder, world, s.words)) {
      after.push_back(*q);
      continue;
    }
    if (!answer.empty() && tells_what_someone_did(s.words)) {
      out.notes.push_back("I took " + quote(s.text) + " as a remark.");
      continue;
    }
    if (context.asked != Asked::kAction)
      if (auto actions = door_action(grounder, world, context, s.words)) {
        door_first.push_back(answer.empty());
        doors.push_back(&s);
        door_actions.push_back(*actions);
        continue;
      }
    if (corrects && answer.empty()) {
      Marker m = marker(s.words);
      if (m.length > 0 && m.length < s.words.size()) {
        lead = m;
        lead_in_answer = true;
        correcting = correcting || m.strong;
        weak = weak || !m.strong;
      }
    }
    answer.push_back(&s);
  }
  // What the answer is read as: after an undo or a strong marker, the
  // answer the undone question should have had (about the thing of the
  // last goal); a weak marker ("nah") corrects only when the answer names
  // that thing or says "not" its place.
  ReplyContext at = context;
  std::string answer_text = joined(answer);
  if (lead_in_answer && !answer.empty()) {
    const Words& first = answer.front()->words;
    std::size_t cut = std::min(lead.length, first.size());
    marker_said = quoted_words(Words(first.begin(), first.begin() + static_cast<std::ptrdiff_t>(cut)));
    answer_text = quoted_words(Words(first.begin() + static_cast<std::ptrdiff_t>(cut), first.end()));
    if (answer.size() > 1)
      answer_text += ", " + joined(std::vector<const Segment*>(answer.begin() + 1, answer.end()));
  }
  if (weak && !correcting && context.last_goal && !answer.empty()) {
    // It names the last thing, or says "not" the last place.
    Words all = reply_words(answer_text);
    bool names_last = false;
    for (const std::string& part : name_parts(world.universe->info(context.last_goal->object).category))
      if (std::find(all.begin(), all.end(), part) != all.end() || std::find(all.begin(), all.end(), part + "s") != all.end())
        names_last = true;
    bool not_there = std::find(all.begin(), all.end(), "not") != all.end();
    correcting = names_last || not_there;
  }
  if (weak && !correcting && !marker_said.empty()) out.notes.push_back("I took " + quote(marker_said) + " as a filler.");
  // A marker before a question or a one-off action alone ("wait, where's
  // the ketchup?") takes nothing back.
  const bool answers = !trim(answer_text).empty();
  if (correcting && before.empty() && !answers && !after.empty()) correcting = false;
  if (correcting && context.last_goal && context.asked == Asked::kGoal && before.empty())
    before.push_back(Command{Command::Kind::kUndo, "", {}, {}});
  if (correcting && context.last_goal && context.asked == Asked::kGoal) {
    at.object = context.last_goal->object;
    at.recent_place = destination(world, GoalGiven{context.last_goal->goal});
    // "not in the drawer" says what was wrong, not what is right.
    std::vector<std::string> kept;
    for (const Segment& s : segments(answer_text))
      if (s.words.empty() || s.words.front() != "not") kept.push_back(s.text);
    answer_text = join(kept, ", ");
    out.after_undo = answer_text;
  }
  // Remarks ("it's soaking", "kids") are dropped when the rest is whole.
  Reply reply = Unusable{};
  bool answered = !trim(answer_text).empty();
  if (answered) {
    reply = read_answer(grounder, world, at, answer_text, out.notes);
    if (!usable(reply) && answer.size() > 1) {
      std::vector<const Segment*> kept;
      std::vector<std::string> dropped;
      for (const Segment* s : answer) {
        if (is_remark(grounder, world, s->words)) dropped.push_back(s->text);
        else kept.push_back(s);
      }
      if (!dropped.empty() && !kept.empty()) {
        Reply retry = read_answer(grounder, world, at, joined(kept), out.notes);
        if (usable(retry)) {
          reply = retry;
          for (const std::string& d : dropped) out.notes.push_back("I took " + quote(d) + " as a remark.");
        }
      }
    }
  }
  // A door action about the goal's own place is part of the goal.
  std::optional<ObjectId> goes_to = destination(world, reply);
  for (std::size_t i = 0; i < doors.size(); ++i) {
    const std::vector<Action>& actions = door_actions[i];
    std::vector<Action> actions_said = door_actions[i];
    // "close the doors", "lids on": the doors of the place the goal names.
    if (goes_to && actions_said.size() > 1 && is_door_word(doors[i]->words.back()))
      std::erase_if(actions_said, [&](const Action& a) { return a.arguments().empty() || a.arguments()[0] != *goes_to; });
    if (actions_said.empty()) actions_said = actions;
    bool own = goes_to && actions_said.size() == 1 && world.domain->actions[actions_said.front().schema].name != "open" &&
               actions_said.front().arguments().size() == 1 && actions_said.front().arguments()[0] == *goes_to;
    if (own) {
      std::string door_text = actions_said.size() < actions.size() ? "close it" : doors[i]->text;
      Reply with = read_answer(grounder, world, at, answer_text + ", " + door_text, out.notes);
      if (usable(with)) {
        reply = with;
        answer_text += ", " + door_text;
        if (correcting) out.after_undo = answer_text;
        continue;
      }
    }
    if (door_first[i]) first_doors.push_back(Command{Command::Kind::kDo, "", {}, actions});
    else after.insert(after.begin(), Command{Command::Kind::kDo, "", {}, actions});
  }
  // "over there by the thingamajig", "here next to the sink": "there" is
  // a spot said by another thing, not the place named last; asked back.
  if (answered && usable(reply) && there_described(reply_words(answer_text)))
    reply = Unusable{"I can't tell which place \"there\" is. Please name the place.", example_replies(world, at), std::nullopt, {}};
  if (answered) {
    std::vector<Action> closings = other_closings(grounder, world, answer_text, reply);
    if (!closings.empty()) after.push_back(Command{Command::Kind::kDo, "", {}, closings});
  }
  // "why are you asking, it's a needle": a "why" said with an answer is
  // the teacher's remark, not a question to answer.
  if (answered && usable(reply))
    std::erase_if(after, [](const Reply& r) {
      const auto* c = std::get_if<Command>(&r);
      return c != nullptr && c->kind == Command::Kind::kWhy;
    });
  for (Reply& r : before) out.acts.push_back(std::move(r));
  for (Reply& r : first_doors) out.acts.push_back(std::move(r));
  // Without an answer, the undo, the question or the action stands alone;
  // with nothing at all, the whole reply's reading (why it is unusable).
  if (answered && (usable(reply) || (before.empty() && after.empty() && first_doors.empty()))) out.acts.push_back(reply);
  for (Reply& r : after) out.acts.push_back(std::move(r));
  if (out.acts.empty()) out.acts.push_back(answered ? reply : whole);
  return out;
}

}  // namespace apprentice::language
