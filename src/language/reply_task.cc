// The task's name in everyday English (language/reply_reading.h): "tidy
// the kitchen", "can you clean up in here?", "we had people over, the
// living room needs cleaning". The structure of the task is in
// reply_structure.cc.
#include <algorithm>
#include <array>

#include "language/generation.h"
#include "language/known_verbs.h"
#include "language/narration.h"
#include "language/reply_reading.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language {

// A word of the world's location ("living" of "living room"): never the
// task's verb.
bool names_location(const std::string& word, const ReplyInput& in) {
  const std::vector<std::string> room = split_words(to_lower(in.world.location));
  return std::find(room.begin(), room.end(), word) != room.end();
}

namespace {

using Words = std::vector<std::string>;

// --- The task's name ---------------------------------------------------------

// Words that only frame a request: "I want you to", "your job is", "let's".
bool is_frame_word(std::string_view w) {
  return is_one_of(w, {"i", "you", "we", "me", "us", "want", "would", "like", "need", "needs", "is", "am", "are",
                       "going", "learn", "how", "time", "it", "teach", "show", "job", "task", "your", "my", "our",
                       "the", "have", "has", "got", "today", "now", "will", "shall", "should", "must", "can",
                       "could", "let", "help", "please", "ok", "so", "first", "about", "ready", "able", "try",
                       "goal", "tonight", "to", "then", "here", "what", "next", "gonna", "going", "be", "this",
                       "learning", "teaching", "want", "wanted", "new", "a"});
}

// The words after the frame: from the first word that is not a frame word.
Words after_frame(const Words& words) {
  std::size_t cut = 0;
  while (cut < words.size() && is_frame_word(words[cut])) ++cut;
  if (cut == words.size()) cut = 0;
  Words rest(words.begin() + static_cast<std::ptrdiff_t>(cut), words.end());
  for (const std::vector<std::string_view>& lead : std::vector<std::vector<std::string_view>>{
           {"let", "us"}, {"help", "me"}, {"help", "us"}, {"please"}, {"we", "will"}, {"you", "will"}, {"i", "will"}})
    if (rest.size() > lead.size() && std::equal(lead.begin(), lead.end(), rest.begin()))
      rest.erase(rest.begin(), rest.begin() + static_cast<std::ptrdiff_t>(lead.size()));
  while (!rest.empty() && is_one_of(rest.back(), {"today", "now", "please", "again", "tonight", "for", "us", "me"}))
    rest.pop_back();
  return rest;
}

bool verb_like(const std::string& word, const ReplyInput& in, std::string& base) {
  base = in.vocabulary.any_verb(word);
  if (!base.empty()) return true;
  // Without WordNet, any plain word that is not a function word.
  if (in.grounder.lexicon().has_wordnet()) return false;
  if (word.empty() || is_determiner(word) || is_object_pronoun(word) || is_copula(word) || is_auxiliary(word) ||
      is_filler(word) || is_clause_break(word) || !std::all_of(word.begin(), word.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || c == '-';
      }))
    return false;
  base = word;
  return true;
}


// "cleanup", "clean-up": a verb run together with its particle "up", as
// its base form; "" for any other word.
std::string run_together_verb(const std::string& word, const ReplyInput& in) {
  if (word.size() <= 4 || !word.ends_with("up")) return "";
  std::string stem = word.substr(0, word.size() - 2);
  if (stem.ends_with("-")) stem.pop_back();
  return in.vocabulary.any_verb(stem);
}

// A task said by its verb's form after what it is done to: the verb's base
// form and the other words.
struct GerundTask {
  std::string verb;
  Words object;
};

// "the kitchen needs tidying", "kitchen tidying", "the kitchen needs to be
// tidied": the verb's form after what it is done to.
std::optional<GerundTask> gerund_task(const Words& words, const ReplyInput& in) {
  for (std::size_t i = 1; i < words.size(); ++i) {
    const std::string& w = words[i];
    std::string base;
    if (w.ends_with("ing") || w.ends_with("ed")) base = in.vocabulary.any_verb(w);
    if (base.empty()) base = run_together_verb(w, in);
    if (base.empty() || base == w || names_location(w, in)) continue;
    GerundTask task{base, {}};
    for (std::size_t k = 0; k < words.size(); ++k) {
      const std::string& o = words[k];
      if (k == i || is_determiner(o) || is_copula(o) || is_auxiliary(o) || is_particle(o)) continue;
      task.object.push_back(o);
    }
    return task;
  }
  return std::nullopt;
}

// "i need everything put away", "want it all cleaned up": what is wanted
// done to something, said as the verb's form after it; before any other
// verb's form in the reply ("the kids just finished their experiment and
// i need everything put away" is putting away, not finishing).
struct WantedDone {
  std::string verb;
  std::string particle;
  Words object;
};

std::optional<WantedDone> wanted_done(const Words& words, const ReplyInput& in) {
  for (std::size_t i = 0; i + 2 < words.size(); ++i) {
    if (!is_one_of(words[i], {"need", "needs", "want", "wants", "get", "gets"})) continue;
    for (std::size_t k = i + 1; k < words.size() && k <= i + 4; ++k) {
      std::string base = in.vocabulary.any_verb(words[k]);
      if (base.empty() || names_location(words[k], in) || is_determiner(words[k])) continue;
      WantedDone out{base, k + 1 < words.size() && is_particle(words[k + 1]) ? words[k + 1] : "", {}};
      out.object.assign(words.begin() + static_cast<std::ptrdiff_t>(i + 1), words.begin() + static_cast<std::ptrdiff_t>(k));
      if (out.object.empty()) break;
      for (std::size_t r = k + (out.particle.empty() ? 1 : 2); r < words.size(); ++r) out.object.push_back(words[r]);
      return out;
    }
  }
  return std::nullopt;
}

// A verb said somewhere in the reply that names a known task (tidying, or
// a verb WordNet puts close to it), with its particle and the words after
// it: what a request means when the verb it was read with names none. "it's
// end of shift ..., can you help me tidy it up" is tidying, not "end"; "get
// the playroom sorted" sorting, not "get"; "we had people over, the living
// room needs cleaning" cleaning, not "have over". A word after a
// determiner is a noun ("a mess"), and a word of the room's name no verb.
struct TaskVerbSaid {
  std::string verb;
  std::string particle;
  Words object;
};

std::optional<TaskVerbSaid> known_task_verb_said(const std::vector<Words>& said, const ReplyInput& in) {
  const Lexicon& lexicon = in.grounder.lexicon();
  for (const Words& piece : said)
    for (std::size_t i = 0; i < piece.size(); ++i) {
      const std::string& w = piece[i];
      if ((i > 0 && is_determiner(piece[i - 1])) || names_location(w, in) || is_particle(w) || is_determiner(w))
        continue;
      std::string base = in.vocabulary.any_verb(w);
      std::string particle = i + 1 < piece.size() && is_particle(piece[i + 1]) ? piece[i + 1] : "";
      if (base.empty() && !(base = run_together_verb(w, in)).empty()) particle = "up";
      if (base.empty()) continue;
      if (!names_a_known_task(lexicon, base, particle)) continue;
      TaskVerbSaid out{base, particle, {}};
      for (std::size_t k = i + 1; k < piece.size(); ++k)
        if (!is_particle(piece[k]) && !is_determiner(piece[k])) out.object.push_back(piece[k]);
      // "the kitchen needs cleaning": what it is done to comes first.
      if (out.object.empty())
        for (std::size_t k = 0; k < i; ++k)
          if (!is_determiner(piece[k]) && !is_copula(piece[k]) && !is_auxiliary(piece[k]) && !is_frame_word(piece[k]))
            out.object.push_back(piece[k]);
      return out;
    }
  return std::nullopt;
}

// The task named by its verb and what it is done to. The task's place is
// the world's location: said ("clean up the bathroom after my shower",
// "tidy the garden shed"), pointed at ("tidy up in here", "this room",
// "it" for the room), said as another name for a room ("the lounge", "the
// kids room"), or said as a time ("clean up after the party"); never a
// filler or a word no one knows. What the task is done to is kept when it
// is neither ("put the groceries away", "do the laundry"). A task over the
// room said with another verb than the agent's ("clean up", "straighten")
// is the agent's task verb WordNet puts closest (known_verbs.h), with a
// note for the read-back. `up_first`: "up" said right after the verb.
// WordNet's classes of the places a task is done in, besides rooms:
// "shed", "greenhouse" (buildings), "station", "gym" (facilities), "boat"
// (vessels). Not "establishment": "the office" of a study stays as said. Not
// "structure" or "area": a cupboard is both; nor "workplace": "the
// laundry" is the washing before it is a room.
constexpr std::array<std::string_view, 3> kRoomlikeClasses{"building", "facility", "vessel"};

// Whether what a task is done to is everything in the room: "everything",
// "it all", "all the stuff in here", "all of this".
bool names_everything_here(const Words& object) {
  bool whole = false;
  for (const std::string& w : object) {
    if (is_one_of(w, {"everything", "everythin", "stuff", "things", "all"})) whole = true;
    else if (!is_one_of(w, {"it", "of", "this", "that", "these", "in", "here", "the", "room", "place", "lot"}))
      return false;
  }
  return whole;
}

TaskNamed task_named(const ReplyInput& in, const std::string& verb, const std::string& particle, bool up, Words object,
                     bool up_first) {
  Words room = split_words(to_lower(in.world.location));
  // "put everything away": what the task is done to is the room.
  const bool everything = names_everything_here(object);
  if (!room.empty() && everything) object = room;
  if (!room.empty()) {
    // "after the party", "before I leave": a time, not what the task is done to.
    auto time = std::find_if(object.begin(), object.end(), [](const std::string& w) {
      return is_one_of(w, {"after", "before", "around", "for", "at", "when", "while", "until", "since"});
    });
    bool when = time == object.begin() && !object.empty();
    object.erase(time, object.end());
    auto at = std::search(object.begin(), object.end(), room.begin(), room.end());
    const Lexicon& lexicon = in.grounder.lexicon();
    // A word for a room or a building that no thing of the world is
    // called ("the potting shed" of a greenhouse, "the station" of the
    // nurses' station) names the room the agent is in: the task is over
    // the world's location, never over a room the agent cannot see.
    auto names_a_thing_here = [&](const std::string& w) {
      return std::any_of(in.world.universe->objects().begin(), in.world.universe->objects().end(),
                         [&](const ObjectInfo& o) {
                           const std::vector<std::string> parts = name_parts(o.category);
                           return std::find(parts.begin(), parts.end(), w) != parts.end();
                         });
    };
    auto names_a_kind_here = [&](const std::string& w) {
      return std::any_of(in.world.universe->objects().begin(), in.world.universe->objects().end(),
                         [&](const ObjectInfo& o) { return name_parts(o.category).back() == w; });
    };
    auto roomlike = [&](const std::string& w) {
      if (is_one_of(w, {"in", "here", "this", "one", "room", "place", "it", "ugh", "um", "lol", "hmm", "oh", "so"}))
        return true;
      if (lexicon.has_wordnet() && !lexicon.knows(w)) return true;
      std::vector<std::string> one{w};
      if (!lexicon.kinds_under("room", one).empty()) return true;
      // "the shop" of a workshop: the end of the location's one-word name.
      const std::string location = to_lower(in.world.location);
      if (w.size() >= 3 && location.size() > w.size() && location.ends_with(w) &&
          location.find_first_of(" -") == std::string::npos)
        return true;
      // "my office" of a home office, "the gym" of a garage gym: the last
      // word of the location's name is the room it names, when no thing
      // here is called so (a gym bag is a bag).
      const Words location_words = split_words(location);
      if (location_words.size() > 1 && location_words.back() == w && !names_a_kind_here(w)) return true;
      // "the laundry" in a laundry room is the washing.
      if (names_a_thing_here(w) || names_location(w, in)) return false;
      return std::any_of(kRoomlikeClasses.begin(), kRoomlikeClasses.end(),
                         [&](std::string_view c) { return !lexicon.kinds_under(c, one).empty(); });
    };
    bool pointed = object.empty() || std::any_of(object.begin(), object.end(), roomlike);
    if (at != object.end() || pointed || when) object = room;
  }
  std::string name = verb_name(verb, particle);
  if (particle == "off" || particle == "down" || particle == "over" || particle == "aside") name = verb + " " + particle;
  // "clean up after the party": "up" stays before a preposition, whose
  // object is the task's.
  if (room.empty() && !object.empty() && is_one_of(object.front(), {"after", "before", "around"}) && up_first)
    name = verb + " up";
  std::string note;
  if (!room.empty() && object == room) {
    const std::string said_particle = particle.empty() && up ? "up" : particle;
    auto taken = known_task_verb(in.grounder.lexicon(), verb, said_particle);
    if (!taken && everything && !names_a_known_task(in.grounder.lexicon(), verb, said_particle))
      taken = task_verb_over_everything(verb, said_particle);
    if (taken) {
      name = taken->verb;
      note = taken->note;
    }
  }
  for (const std::string& w : object) name += " " + w;
  return TaskNamed{name, note};
}

}  // namespace

Reply read_task(const ReplyInput& in) {
  // The piece that says what to do ("The kitchen is a mess, please tidy
  // it." has two). Each piece without its frame, and whether it describes
  // rather than asks: its second word is "is" ("the garage is a mess"), or it starts
  // with a subject ("the kids left a mess"; "the task is to ..." is a
  // frame). Its first word is then a noun, even where WordNet knows a verb
  // ("to garage", "to kid").
  std::vector<Words> said;
  std::vector<bool> describes;
  std::vector<Words> framed;  // the pieces as said, frame and all
  for (Words piece : comma_pieces(without_fillers(in.words, in.vocabulary))) {
    // "end of (the) day": a word before "of" is a noun, and the phrase a
    // time, not the request.
    if (piece.size() > 2 && piece[1] == "of") {
      std::size_t cut = 2 + (is_determiner(piece[2]) ? 1 : 0) + 1;
      piece.erase(piece.begin(), piece.begin() + static_cast<std::ptrdiff_t>(std::min(cut, piece.size())));
      if (piece.empty()) continue;
    }
    framed.push_back(piece);
    said.push_back(after_frame(piece));
    const Words& rest = said.back();
    bool subject_first = piece.size() > 1 && is_determiner(piece[0]) && !is_frame_word(piece[1]);
    bool copula_second = rest.size() > 1 && (is_copula(rest[1]) || rest[1] == "looks" || rest[1] == "needs");
    describes.push_back(subject_first || copula_second);
  }
  std::string verb;
  const Words* words = nullptr;
  // A piece said as a request ("can you help me turn it over?") before one
  // that tells ("room 412 just checked out").
  // Then a piece that starts with a verb as a request says it ("Dishes.
  // Put them away.": "dishes" is not "to dish").
  for (int pass = 0; pass < 3; ++pass)
    for (std::size_t i = 0; i < said.size() && words == nullptr; ++i) {
      const Words& piece = said[i];
      // Said as a request, with its verb as a request says it ("been" in
      // "it's been a long day" is not).
      const bool plain = !piece.empty() && in.vocabulary.any_verb(piece.front()) == piece.front();
      if ((pass == 0 && (piece.size() == framed[i].size() || !plain)) || (pass == 1 && !plain)) continue;
      // "I just got back from the store": "back" is a particle here, not "to back".
      if (!piece.empty() && !describes[i] && !is_determiner(piece.front()) && !is_object_pronoun(piece.front()) &&
          !is_particle(piece.front()) && !names_location(piece.front(), in) && verb_like(piece.front(), in, verb))
        words = &piece;
    }
  if (!words) {
    Words all;
    for (const Words& piece : said) all.insert(all.end(), piece.begin(), piece.end());
    if (auto wanted = wanted_done(all, in))
      return task_named(in, wanted->verb, wanted->particle, wanted->particle == "up", std::move(wanted->object), false);
    if (auto named = gerund_task(all, in)) return task_named(in, named->verb, "", false, std::move(named->object), false);
    return unusable(in, Problem{"I need the name of a task, said as what to do, such as \"" +
                                    example_replies(in.world, in.context).front() + "\".",
                                std::nullopt});
  }
  std::string particle;
  Words object;
  for (std::size_t i = 1; i < words->size(); ++i) {
    const std::string& w = (*words)[i];
    // ("tidy up the cabin before we hand the boat back": the time said
    // after the task holds no particle of its verb.)
    if (is_one_of(w, {"before", "after", "when", "while", "until"})) {
      object.insert(object.end(), words->begin() + static_cast<std::ptrdiff_t>(i), words->end());
      break;
    }
    if (is_particle(w)) {
      if (w != "up" && particle.empty()) particle = w;  // "tidy up" is "tidy"
    } else if (!is_determiner(w) || (w == "all" && is_one_of((*words)[i - 1], {"it", "this", "them"}))) {
      // ("put it all away": "all" says it is everything.)
      object.push_back(w);
    }
  }
  bool up = std::find(words->begin() + 1, words->end(), "up") != words->end();
  bool up_first = words->size() > 1 && (*words)[1] == "up";
  if (!names_a_known_task(in.grounder.lexicon(), verb, particle.empty() && up ? "up" : particle))
    if (auto other = known_task_verb_said(said, in)) {
      verb = other->verb;
      up = other->particle == "up";
      up_first = up;
      particle = up ? "" : other->particle;
      object = std::move(other->object);
    }
  // "a bit", "for me", "right now" say nothing about the task.
  while (!object.empty() && is_one_of(object.back(), {"bit", "little", "quickly", "now", "today", "please", "me"}))
    object.pop_back();
  // "tidy it": what "it" is, from another piece ("the kitchen is a mess").
  if (object.size() == 1 && is_object_pronoun(object.front())) {
    for (const Words& piece : said) {
      if (&piece == words) continue;
      Words noun;
      for (const std::string& w : piece) {
        if (is_copula(w) || is_auxiliary(w)) break;
        if (!is_determiner(w)) noun.push_back(w);
      }
      if (!noun.empty()) {
        object = noun;
        break;
      }
    }
  }
  return task_named(in, verb, particle, up, std::move(object), up_first);
}

}  // namespace apprentice::language
