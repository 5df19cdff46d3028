// A reply cut into segments, and what each segment may be besides part of
// the answer (read_acts, reply_acts.cc): fillers, an undo, a correction's
// marker, a question of the teacher's, an ending of the session, a request
// for help, a one-off door action.
#include <algorithm>

#include "language/generation.h"
#include "language/narration.h"
#include "language/parser.h"
#include "language/reply_acts_parts.h"
#include "language/reply_reading.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language::acts {
// Words that only set the tone: "um", "ugh", "lol", "ok so", "oh and".
bool is_interjection(std::string_view w) {
  return is_one_of(w, {"um", "umm", "ummm", "uh", "uhh", "er", "erm", "ugh", "hmm", "hmmm", "hm", "mm", "mmm", "ok", "so", "oh",
                       "lol", "haha", "well", "hey", "hi", "hiya", "hello", "btw", "alright", "and", "also", "plus",
                       "please", "right", "anyway", "yeah", "ah", "aha", "ooh", "argh", "gosh", "jeez", "omg", "idk",
                       "lemme", "see", "thanks", "thank", "you", "cheers", "sorry", "mate", "buddy", "kk", "ew", "eww",
                       "ewww", "yuck", "ick", "god", "geez", "wow", "damn", "duh", "obv", "obviously", "dude", "pfft",
                       "meh", "ha", "lmao", "tho", "though", "typo", "typos", "autocorrect", "huh", "hmph"});
}

// The words of a correction's marker: "no wait", "oops", "nah", "wait what"
// (and "hang on", "hold on": two words, read by marker()).
bool is_marker(std::string_view w) {
  return is_one_of(w, {"no", "nah", "nope", "wait", "oops", "whoops", "actually", "sorry", "what", "oh", "ugh",
                       "hmm", "um"});
}

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
  // "the dirty towel goes in the hamper not on the hook": where a thing does
  // not go, said after where it goes, is a segment of its own, as with a
  // comma before it. (Not "does not go", "is not in".)
  for (std::size_t k = 0; k < out.size(); ++k) {
    const Words& w = out[k].words;
    for (std::size_t i = 2; i + 1 < w.size(); ++i)
      if (w[i] == "not" && is_one_of(w[i + 1], {"in", "on", "into", "onto", "inside", "the", "a", "my", "your"}) &&
          !is_copula(w[i - 1]) && !is_auxiliary(w[i - 1]) && !is_one_of(w[i - 1], {"do", "does", "did"})) {
        Words first(w.begin(), w.begin() + static_cast<std::ptrdiff_t>(i));
        Words second(w.begin() + static_cast<std::ptrdiff_t>(i), w.end());
        out[k] = {quoted_words(first), first};
        out.insert(out.begin() + static_cast<std::ptrdiff_t>(k + 1), Segment{quoted_words(second), second});
        break;
      }
  }
  // "leave the rake where it is and tell me what's left": a request to be
  // told something is a segment of its own.
  for (std::size_t k = 0; k < out.size(); ++k) {
    const Words& w = out[k].words;
    for (std::size_t i = 1; i + 2 < w.size(); ++i)
      if (w[i] == "and" && is_one_of(w[i + 1], {"tell", "show"}) && w[i + 2] == "me") {
        Words first(w.begin(), w.begin() + static_cast<std::ptrdiff_t>(i));
        Words second(w.begin() + static_cast<std::ptrdiff_t>(i + 1), w.end());
        out[k] = {quoted_words(first), first};
        out.insert(out.begin() + static_cast<std::ptrdiff_t>(k + 1), Segment{quoted_words(second), second});
        break;
      }
  }
  return out;
}

Words without_interjections(Words words) {
  while (!words.empty() && is_interjection(words.front())) words.erase(words.begin());
  return words;
}

bool is_connective(std::string_view w) { return is_one_of(w, {"and", "then", "now"}); }

Words without_leading_connectives(Words words) {
  std::size_t first = 0;
  while (first < words.size() && is_connective(words[first])) ++first;
  words.erase(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(first));
  return words;
}

bool has(const Words& words, std::initializer_list<std::string_view> phrase) {
  return std::search(words.begin(), words.end(), phrase.begin(), phrase.end()) != words.end();
}

// "undo", "scratch that", "go back one", "that was wrong": how many undos
// (0: not an undo).
// "put it back", "move them back where they were": the last thing moved,
// back where it was, with no place said after "back".
bool puts_it_back(const Words& words) {
  const auto back = std::find(words.begin(), words.end(), "back");
  if (back == words.end() || back == words.begin()) return false;
  const Words before(words.begin(), back);
  if (!is_one_of(before.front(), {"put", "move", "bring", "take"}) || before.size() > 3) return false;
  if (!std::all_of(before.begin() + 1, before.end(),
                   [](const std::string& w) { return is_object_pronoun(w) || is_one_of(w, {"that", "those", "them"}); }))
    return false;
  return std::all_of(back + 1, words.end(), [](const std::string& w) {
    return is_one_of(w, {"where", "it", "they", "was", "were", "before", "to", "how", "please", "now"});
  });
}

int undos(const Words& said) {
  Words words;
  for (const std::string& w : said)
    if (!is_marker(w) && !is_interjection(w)) words.push_back(w);
  if (words.empty()) return 0;
  // ("put it back, it leaks": with why after it.)
  const auto comma = std::find(words.begin(), words.end(), ",");
  const bool why_after = comma != words.end() && comma + 1 != words.end() &&
                         is_one_of(*(comma + 1), {"it", "its", "it's", "they", "theyre", "they're", "that", "thats"});
  if (puts_it_back(why_after ? Words(words.begin(), comma) : words)) return 1;
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

bool confirms_the_old_place(const Words& said) {
  // (Markers only before the place: "right" ends the phrase.)
  std::size_t from = 0;
  while (from < said.size() && (is_marker(said[from]) || is_interjection(said[from]))) ++from;
  const Words words(said.begin() + static_cast<std::ptrdiff_t>(from), said.end());
  if (words.size() < 2 || words.size() > 6) return false;
  const auto was = std::find_if(words.begin(), words.end(), [](const std::string& w) { return is_one_of(w, {"was", "were"}); });
  if (was == words.end() || was + 1 == words.end() || *(was + 1) != "right") return false;
  return std::none_of(words.begin(), words.end(), [](const std::string& w) { return is_negation(w); });
}

Marker marker(const Words& words) {
  Marker m;
  int noes = 0;
  while (m.length < words.size()) {
    // "hang on", "hold on", "hold up": as "wait".
    if (m.length + 1 < words.size() && is_one_of(words[m.length], {"hang", "hold"}) &&
        is_one_of(words[m.length + 1], {"on", "up"})) {
      m.length += 2;
      m.strong = true;
      continue;
    }
    if (!is_marker(words[m.length]) && !is_interjection(words[m.length])) break;
    const std::string& w = words[m.length];
    // "oops, right bin": "right" before a word of the answer is a side.
    if (w == "right" && m.length + 1 < words.size() && !is_marker(words[m.length + 1]) &&
        !is_interjection(words[m.length + 1]))
      break;
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
namespace {

// The things, then the places, a why-question names by their names' words
// ("why did you put the glove in the right basket": the gloves, then the
// right basket; "why is the closet still open": the closet). Each noun
// phrase is the run of words that may belong to names here.
std::vector<ObjectId> things_asked_why(const Grounder& grounder, const World& world, const Words& words) {
  ReferenceContext context{world, grounder.lexicon(), std::nullopt};
  context.partial_names = true;
  std::vector<ObjectId> items, places;
  Words phrase;
  auto flush = [&] {
    if (phrase.empty()) return;
    auto found = candidates_for(NounPhrase{"", phrase}, Role::kAny, context);
    if (const auto* set = std::get_if<CandidateSet>(&found))
      for (ObjectId id : set->objects)
        (world.universe->info(id).kind == ObjectKind::kItem ? items : places).push_back(id);
    phrase.clear();
  };
  for (std::size_t i = 1; i < words.size(); ++i) {
    const std::string& w = words[i];
    const bool function_word = is_determiner(w) || is_object_pronoun(w) || is_copula(w) || is_auxiliary(w) ||
                               is_particle(w) || is_clause_break(w) || is_negation(w) ||
                               is_one_of(w, {"in", "on", "into", "onto", "to", "at", "from", "with", "you", "i", "did",
                                             "do", "does", "put", "throw", "out", "away", "still", "so", "before",
                                             "now", "there", "here", "that", "go", "goes", "my"});
    if (function_word) flush();
    else phrase.push_back(w);
  }
  flush();
  items.insert(items.end(), places.begin(), places.end());
  return items;
}

}  // namespace

std::optional<Command> question(const Grounder& grounder, const World& world, const Words& said) {
  Words words = said;
  for (;;) {
    // ("hang on why did you ...": a marker of two words.)
    const Marker m = marker(words);
    if (m.length > 0 && m.length < words.size() && words.front() != "what") {
      words.erase(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(m.length));
    } else if (!words.empty() && (is_interjection(words.front()) || is_marker(words.front())) && words.front() != "what") {
      words.erase(words.begin());
    } else if (words.size() > 1 && is_one_of(words.front(), {"but", "and", "so"}) &&
               is_one_of(words[1], {"why", "where", "what", "whats", "wheres", "whys", "how"})) {
      words.erase(words.begin());  // "ok but why the hook at first"
    } else {
      break;
    }
  }
  // "tell me what's left", "can you tell me where the soap is".
  for (std::size_t i = 0; i + 2 < words.size() && i < 3; ++i)
    if (is_one_of(words[i], {"tell", "show"}) && words[i + 1] == "me" &&
        is_one_of(words[i + 2], {"what", "where", "why", "how"})) {
      words.erase(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(i + 2));
      break;
    }
  if (words.empty()) return std::nullopt;
  // "wheres the pacifier", "where r the diapers", "whys the drawer open":
  // as typed in a hurry.
  if (is_one_of(words.front(), {"wheres", "whys", "whats"})) {
    words.front().pop_back();
    words.insert(words.begin() + 1, "is");
  }
  if (words.size() > 1 && words.front() == "where" && is_one_of(words[1], {"r", "re"})) words[1] = "are";
  const std::string& first = words.front();
  if (first == "why") {
    Command why{Command::Kind::kWhy, join(words, " "), things_asked_why(grounder, world, words), {}};
    why.earlier = std::any_of(words.begin(), words.end(),
                              [](const std::string& w) { return is_one_of(w, {"before", "earlier", "first"}); });
    why.asking = std::any_of(words.begin(), words.end(), [](const std::string& w) {
      return is_one_of(w, {"ask", "asked", "asking", "propose", "proposed", "proposing", "suggest", "suggested",
                           "suggesting"});
    });
    return why;
  }
  // "does the dirty towel still go in the hamper?": where it goes, and
  // where that came from, as "why" answers it.
  if (is_one_of(first, {"does", "do", "should", "will"}) && words.size() > 2 &&
      std::any_of(words.begin() + 1, words.end(), [](const std::string& w) { return is_verb_of_going(w); })) {
    std::vector<ObjectId> things = things_asked_why(grounder, world, words);
    if (!things.empty() && world.universe->info(things.front()).kind == ObjectKind::kItem)
      return Command{Command::Kind::kWhy, join(words, " "), things, {}};
    // ("does a dirty t shirt go in the laundry basket?", with no dirty t
    // shirt here: a question still, answered by what is not seen.)
    const auto going = std::find_if(words.begin() + 1, words.end(), [](const std::string& w) { return is_verb_of_going(w); });
    Words thing;
    for (auto w = words.begin() + 1; w != going; ++w)
      if (!is_determiner(*w) && !is_one_of(*w, {"still", "really", "usually", "always"})) thing.push_back(*w);
    if (!thing.empty()) return Command{Command::Kind::kWhere, join(thing, " "), {}, {}};
  }
  if (first == "where" && words.size() > 1 &&
      is_one_of(words[1], {"is", "are", "did", "does", "do", "has", "have", "was", "were", "would", "had"})) {
    Words thing;
    for (std::size_t i = 2; i < words.size(); ++i)
      if (!is_one_of(words[i], {"you", "it", "go", "put", "gone", "now", "end", "up", "the", "my", "other", "did",
                                "would", "had"}))
        thing.push_back(words[i]);
    if (thing.empty()) return std::nullopt;
    std::string phrase = join(thing, " ");
    ReferenceContext context{world, grounder.lexicon(), std::nullopt};
    context.partial_names = true;
    auto found = candidates_for(NounPhrase{"", thing}, Role::kItem, context);
    // ("where'd you put the dogs ball": a word nothing is called, before a
    // name's last word, leaves that word to name the thing.)
    if (!std::holds_alternative<CandidateSet>(found) && thing.size() > 1)
      found = candidates_for(NounPhrase{"", {thing.back()}}, Role::kItem, context);
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
  // "is everything put away now?", "are we done?" asked, not said: what is
  // left answers it.
  const bool everything = words.size() > 2 && is_one_of(words[1], {"everything", "it", "all", "we"}) &&
                          (has(words, {"away"}) || has(words, {"done"}) || has(words, {"finished"}) ||
                           has(words, {"tidy"}) || has(words, {"clean"}) || has(words, {"clear"}));
  if (is_one_of(first, {"is", "are"}) && everything && words.size() <= 8) return Command{Command::Kind::kWhatsLeft, "", {}, {}};
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
  // "what do you do exactly?", "what does this thing do?": what the agent is for.
  bool what_you_do = words.front() == "what" && (in_order({"do", "you", "do"}) || in_order({"does", "this", "do"}));
  bool can_you_do = in_order({"can", "you", "do"}) || in_order({"could", "you", "do"}) ||
                    has(words, {"able", "to", "do"}) || what_you_do;
  // "how does this work?", "how do I use you?": how the teaching goes.
  bool how_it_works = words.front() == "how" && any_of({"work", "works", "use", "start"});
  bool to_say = std::any_of(words.begin(), words.end(), [](const std::string& w) {
    return is_one_of(w, {"say", "type", "write", "answer"});
  });
  return (you_do || can_you_do || to_say || how_it_works) && words.size() <= 10;
}

// Words that begin a clause of condition or reason: "if", "unless", "so".
bool is_subordinator(std::string_view w) {
  return is_one_of(w, {"if", "unless", "when", "whenever", "once", "because", "since", "so", "while", "though",
                       "although", "cause", "cuz", "coz"});
}

std::size_t what_someone_did_from(const Words& words) {
  for (std::size_t i = 1; i < words.size(); ++i)
    if (words[i] == "left" && is_one_of(words[i - 1], {"you", "someone", "somebody", "they", "he", "she", "we", "i",
                                                        "kids", "who", "guest", "guests"}))
      return i - 1;
  return words.size();
}

// "close the top drawer", "shut both drawers", "open the compost bin
// first": the actions, or nullopt when the segment is not such a command.
std::optional<std::vector<Action>> door_action(const Grounder& grounder, const World& world,
                                               const ReplyContext& context, const Words& said) {
  Words words = without_interjections(said);
  // "first shut the fridge", "please close it": an order word or a
  // courtesy before the verb.
  // ("no just shut the door", "actually close the wardrobe": a marker
  // before the command, with no answer before it to correct.)
  while (!words.empty() && (is_connective(words.front()) || is_marker(words.front()) ||
                            is_one_of(words.front(), {"can", "could", "would", "you", "also", "just", "first", "please"})))
    words.erase(words.begin());
  // "open the drawer and leave it open": the second part only says the
  // first again.
  for (std::size_t i = 1; i + 1 < words.size(); ++i)
    if (words[i] == "and" && is_one_of(words[i + 1], {"leave", "keep"})) {
      const Words rest(words.begin() + static_cast<std::ptrdiff_t>(i) + 2, words.end());
      if (rest.size() <= 3 && !rest.empty() && is_object_pronoun(rest.front()) && is_state_word(rest.back())) {
        words.resize(i);
        break;
      }
    }
  // "leave the cabinet open", "keep the closet shut", asked about the task's
  // steps (where it can be no goal's door): the door as said, now.
  const bool about_steps = context.asked == Asked::kTaskStep || context.asked == Asked::kSubtaskEnd;
  // So is a door's state said with "should be" ("the wardrobe should be
  // closed", "the closet needs to be shut").
  // What follows the state says when or why ("leave the cabinet open for
  // now", "keep the cupboard open this time i'm gonna put stuff in it").
  const auto state = std::find_if(words.begin() + (words.empty() ? 0 : 1), words.end(),
                                  [](const std::string& w) { return is_state_word(w); });
  const bool when_or_why_after =
      state != words.end() &&
      (state + 1 == words.end() || is_one_of(*(state + 1), {"for", "this", "now", "till", "until", "so", "because",
                                                            "cause", "i", "we", "while", "as", "today", "please"}));
  if (about_steps && words.size() >= 3 && when_or_why_after) {
    const bool open_said = is_one_of(*state, {"open", "opened"});
    Words object;
    if (is_one_of(words.front(), {"leave", "keep"})) {
      object = Words(words.begin() + 1, state);
    } else if (*(state - 1) == "be") {
      auto modal = std::find_if(words.begin(), state, [](const std::string& w) {
        return is_one_of(w, {"should", "must", "needs", "need", "has", "have", "ought", "can"});
      });
      if (modal != state && modal != words.begin()) object = Words(words.begin(), modal);
    }
    if (!object.empty()) {
      words = std::move(object);
      words.insert(words.begin(), open_said ? "open" : "close");
    }
  }
  // "lock it": the domain has no locks; a locked door is a closed one.
  // ("lock it in the cabinet" puts it there: no door action.)
  if (words.empty() || !is_one_of(words.front(), {"close", "shut", "lock", "open"})) return std::nullopt;
  if (words.front() == "lock" && std::any_of(words.begin(), words.end(), [](const std::string& w) {
        return is_one_of(w, {"in", "into", "inside", "away"});
      }))
    return std::nullopt;
  const bool open = words.front() == "open";
  // "shut the top drawer if it's still open", "close it so the kids can't
  // get in": a clause of condition or reason says when or why, not what.
  // ("close the icebox someone left it open": what a person did, told
  // after the command, is no part of what to close.)
  const auto told = words.begin() + static_cast<std::ptrdiff_t>(std::max<std::size_t>(1, what_someone_did_from(words)));
  Words object(words.begin() + 1, std::find_if(words.begin() + 1, told, [](const std::string& w) {
                 return is_subordinator(w);
               }));
  std::erase_if(object, [](const std::string& w) {
    return is_one_of(w, {"first", "now", "please", "pls", "plz", "too", "again", "up", "properly", "after", "afterwards"});
  });
  if (object.empty()) return std::nullopt;
  bool every = is_one_of(object.front(), {"both", "all", "every", "each"}) || object.back().ends_with("s");
  // "close it", "shut the lid": the place named last, part of an answer;
  // asked about the task's steps, where no answer has a place, the place
  // named last in the conversation ("open the cabinet", then "close it").
  if (!every && (is_object_pronoun(object.back()) || is_door_word(object.back()))) {
    std::size_t named = std::count_if(object.begin(), object.end(), [](const std::string& w) {
      return !is_determiner(w) && !is_object_pronoun(w) && !is_door_word(w);
    });
    if (named == 0 && about_steps && context.recent_place && openable(world, *context.recent_place))
      object = {world.universe->name(*context.recent_place)};
    else if (named == 0)
      return std::nullopt;
  }
  ReplyContext as_action = context;
  as_action.asked = Asked::kAction;
  Reply reply = read_reply_plain(grounder, world, as_action, std::string(open ? "open " : "close ") + join(object, " "));
  if (const auto* given = std::get_if<ActionGiven>(&reply); given && given->more.empty() && !every)
    return std::vector<Action>{given->action};
  // "open the drawer" where there are two: not every drawer, but one to
  // ask about; read as an answer, it is asked back ("Which drawer: ...?").
  if (!every && std::holds_alternative<Ambiguous>(reply)) return std::nullopt;
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

namespace {

// The words of a wish about a door, without what leads into it ("oh and
// please, ...").
Words wish_words(const Words& said) {
  Words words = without_leading_connectives(without_interjections(said));
  while (!words.empty() && (is_marker(words.front()) || is_one_of(words.front(), {"please", "pls", "also", "just"})))
    words.erase(words.begin());
  return words;
}

// The doors a wish names by `place` ("the washer", "it": the place named
// last), as door_action reads "`verb` `place`"; nullopt when none.
std::optional<std::vector<Action>> wished_doors(const Grounder& grounder, const World& world,
                                                const ReplyContext& context, const std::string& verb,
                                                const Words& place) {
  if (place.empty()) return std::nullopt;
  ReplyContext as_step = context;
  as_step.asked = Asked::kTaskStep;
  Words said = {verb};
  said.insert(said.end(), place.begin(), place.end());
  return door_action(grounder, world, as_step, said);
}

}  // namespace

std::optional<std::vector<Action>> doors_left_open(const Grounder& grounder, const World& world,
                                                   const ReplyContext& context, const Words& said) {
  Words words = wish_words(said);
  if (words.size() < 2) return std::nullopt;
  const bool standing = has(words, {"from", "now", "on"}) || has(words, {"always"}) || has(words, {"anymore"}) ||
                        has(words, {"any", "more"}) || has(words, {"for", "good"}) || has(words, {"permanently"}) ||
                        has(words, {"all", "the", "time"}) || has(words, {"in", "the", "future"}) ||
                        has(words, {"never"});
  auto open_at = [&](std::size_t from) {
    return static_cast<std::size_t>(std::find(words.begin() + static_cast<std::ptrdiff_t>(from), words.end(), "open") -
                                    words.begin());
  };
  Words place;
  if (words.front() == "always") words.erase(words.begin());
  const bool open_said = open_at(0) < words.size();
  if (is_one_of(words.front(), {"leave", "keep"}) && standing && open_said) {
    // "leave the washer open from now on", "always keep it open".
    place.assign(words.begin() + 1, words.begin() + static_cast<std::ptrdiff_t>(open_at(1)));
  } else if (words.size() > 3 && words[0] == "i" && is_one_of(words[1], {"want", "need"}) && open_said) {
    // "i want it left open", "i want the washer open from now on".
    place.assign(words.begin() + 2, words.begin() + static_cast<std::ptrdiff_t>(open_at(2)));
  } else if (is_one_of(words.front(), {"do", "dont", "never", "stop"})) {
    // "don't close the washer anymore", "never shut the hamper", "stop
    // closing the cabinet".
    // ("don't close it", with no "anymore": this time only, as said.)
    if ((words.front() == "dont" || words.front() == "do") && !standing) return std::nullopt;
    const std::size_t verb = words.front() == "do" && words.size() > 2 && words[1] == "not" ? 2 : 1;
    if (verb >= words.size() || !is_one_of(words[verb], {"close", "closing", "shut", "shutting"})) return std::nullopt;
    place.assign(words.begin() + static_cast<std::ptrdiff_t>(verb) + 1, words.end());
  } else {
    // "the hamper should stay open", "the washer needs to be left open".
    const auto stay = std::find_if(words.begin(), words.end(), [](const std::string& w) {
      return is_one_of(w, {"stay", "stays", "remain", "remains", "left", "kept"});
    });
    const auto modal = std::find_if(words.begin(), stay, [](const std::string& w) {
      return is_one_of(w, {"should", "must", "needs", "need", "can", "has", "have"});
    });
    if (stay == words.end() || modal == stay || modal == words.begin() || open_at(0) >= words.size()) return std::nullopt;
    place.assign(words.begin(), modal);
  }
  std::erase_if(place, [](const std::string& w) {
    return is_one_of(w, {"left", "kept", "always", "anymore", "now", "from", "on", "again", "please"});
  });
  return wished_doors(grounder, world, context, "open", place);
}

std::optional<std::vector<Action>> doors_kept_closed(const Grounder& grounder, const World& world,
                                                     const ReplyContext& context, const Words& said) {
  Words words = wish_words(said);
  if (words.size() < 2) return std::nullopt;
  auto closed_at = [&](std::size_t from) {
    return static_cast<std::size_t>(
        std::find_if(words.begin() + static_cast<std::ptrdiff_t>(from), words.end(),
                     [](const std::string& w) { return is_one_of(w, {"closed", "shut", "close"}); }) -
        words.begin());
  };
  if (closed_at(0) >= words.size()) return std::nullopt;
  const bool stays = std::any_of(words.begin(), words.end(), [](const std::string& w) {
    return is_one_of(w, {"stay", "stays", "remain", "remains"});
  });
  const bool standing = stays || has(words, {"from", "now", "on"}) || has(words, {"always"}) ||
                        has(words, {"every", "time"}) || has(words, {"for", "good"}) ||
                        has(words, {"all", "the", "time"}) || has(words, {"in", "the", "future"});
  if (!standing) return std::nullopt;
  Words place;
  if (words.front() == "always") words.erase(words.begin());
  if (is_one_of(words.front(), {"keep", "leave"})) {
    // "keep the cabinet closed from now on".
    place.assign(words.begin() + 1, words.begin() + static_cast<std::ptrdiff_t>(closed_at(1)));
  } else if (is_one_of(words.front(), {"close", "shut"})) {
    // "always close the toy box", "shut it every time".
    place.assign(words.begin() + 1, words.end());
  } else {
    // "this one stays closed", "the bottom drawer should always be shut".
    const auto verb = std::find_if(words.begin(), words.end(), [](const std::string& w) {
      return is_one_of(w, {"stay", "stays", "remain", "remains", "should", "must", "needs", "need", "has", "is",
                           "always"});
    });
    if (verb == words.begin() || verb == words.end()) return std::nullopt;
    place.assign(words.begin(), verb);
  }
  std::erase_if(place, [](const std::string& w) {
    return is_one_of(w, {"always", "from", "now", "on", "every", "time", "again", "please", "for", "good", "all", "the",
                         "in", "future"});
  });
  // "this one", "that one": the place named last.
  if (place == Words{"this", "one"} || place == Words{"that", "one"} || place == Words{"this"} || place == Words{"that"})
    place = {"it"};
  return wished_doors(grounder, world, context, "close", place);
}

}  // namespace apprentice::language::acts
