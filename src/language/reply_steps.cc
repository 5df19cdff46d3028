// Several steps of the task in one reply (read_acts, reply_acts.cc):
// "clear the counter, then the table", "that's it for the desk, now sort
// the bookshelf".
#include <algorithm>

#include "language/generation.h"
#include "language/narration.h"
#include "language/parser.h"
#include "language/known_verbs.h"
#include "language/reply_acts_parts.h"
#include "language/reply_reading.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language::acts {
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
      current = without_leading_connectives(std::move(current));
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

// One part cut where "and" comes before a determiner: "clear the counter
// and the trolley" is two parts, "clear the counter" and "the trolley"
// (which takes the first part's verb); "empty the red and yellow buckets"
// is not cut. Each part must then read as a step, or the reply is read
// whole.
std::vector<Words> parts_at_and(const std::vector<Words>& parts) {
  if (parts.size() != 1) return parts;
  const Words& part = parts.front();
  for (std::size_t i = 1; i + 1 < part.size(); ++i)
    if (part[i] == "and" && is_determiner(part[i + 1]))
      return {Words(part.begin(), part.begin() + static_cast<std::ptrdiff_t>(i)),
              Words(part.begin() + static_cast<std::ptrdiff_t>(i + 1), part.end())};
  return parts;
}

// "counter next", "the folding table": a place of the world said with no
// verb and nothing said of it ("the table's clear", "the bag still has
// stuff in it" say something).
// The places it may name, or none.
std::vector<ObjectId> places_named_alone(const Grounder& grounder, const World& world, const Words& part) {
  ReferenceContext context{world, grounder.lexicon(), std::nullopt};
  std::vector<ObjectId> places;
  for (const std::string& w : part) {
    if (is_copula(w) || is_one_of(w, {"has", "have", "still", "more", "there", "it", "that", "this"})) return {};
    if (is_determiner(w)) continue;
    if (const auto found = candidates_for(NounPhrase{"", {w}}, Role::kPlace, context);
        const auto* set = std::get_if<CandidateSet>(&found))
      for (ObjectId o : set->objects)
        if (std::find(places.begin(), places.end(), o) == places.end()) places.push_back(o);
  }
  return places;
}

bool names_a_place_alone(const Grounder& grounder, const World& world, const Words& part) {
  return !places_named_alone(grounder, world, part).empty();
}

// "detergent and stain remover go in the cabinet": a verb of going and a
// thing here it is said of.
bool says_where_things_go(const Grounder& grounder, const World& world, const Words& part) {
  if (std::none_of(part.begin(), part.end(), [](const std::string& w) { return is_verb_of_going(w); })) return false;
  ReferenceContext context{world, grounder.lexicon(), std::nullopt};
  return std::any_of(part.begin(), part.end(), [&](const std::string& w) {
    if (is_determiner(w) || is_object_pronoun(w)) return false;
    const auto found = candidates_for(NounPhrase{"", {w}}, Role::kItem, context);
    const auto* set = std::get_if<CandidateSet>(&found);
    return set != nullptr && std::any_of(set->objects.begin(), set->objects.end(), [&](ObjectId o) {
             return world.universe->info(o).kind == ObjectKind::kItem;
           });
  });
}

// "clear" and "the table": the part with the verb before it.
Words with_verb(const std::string& verb, const Words& part) {
  Words with = split_words(verb);
  with.insert(with.end(), part.begin(), part.end());
  return with;
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
                                                                      std::string_view text, const Reply& whole,
                                                                      std::vector<std::string>& goals_ahead) {
  if (context.asked != Asked::kTaskStep && context.asked != Asked::kSubtaskEnd) return std::nullopt;
  std::vector<Words> parts = parts_at_and(step_parts(text));
  // ("you know this one?? desk first, then the floor": a remark before
  // the parts is none of them.)
  while (parts.size() > 2 && is_remark(grounder, world, without_interjections(parts.front())))
    parts.erase(parts.begin());
  if (parts.size() < 2 || parts.size() > 4) return std::nullopt;
  std::optional<Reply> first;
  std::vector<std::string> rest;
  std::string verb;  // the last verb said, for a part without one
  std::vector<ObjectId> last_places;  // the places of the last part read
  bool names_a_part = false;  // "that's it, we're done" is one ending
  ReplyContext at = context;
  // "shut the drawer... no wait it's already shut. just clear the table":
  // a correction inside the reply is read with the reply's acts.
  for (std::size_t i = 1; i < parts.size(); ++i)
    if (const Marker m = marker(parts[i]); m.length > 0 && m.strong) return std::nullopt;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    // "ok now shut the cupboard": "now" was not first until "ok" went.
    Words part = without_leading_connectives(without_interjections(parts[i]));
    if (part.empty()) return std::nullopt;
    // "ok now shut the cupboard, then do the piano": a one-off door action
    // first, done now, and the parts after it read in turn.
    if (auto actions = door_action(grounder, world, at, part)) {
      // ("that's all, leave the cabinet open": a one-off action said after
      // a part is the reply's acts' to read.)
      if (i > 0) return std::nullopt;
      first = Command{Command::Kind::kDo, "", {}, *actions};
      at.asked = Asked::kTaskStep;
      continue;
    }
    // Where things go, said after a part: for the part's questions.
    if (i > 0 && first && std::holds_alternative<SubtaskNamed>(*first) && says_where_things_go(grounder, world, part)) {
      goals_ahead.push_back(quoted_words(part));
      continue;
    }
    // ("the folding table, clear it": "it" is the place of the part before.)
    const bool pronoun = std::any_of(part.begin(), part.end(), [](const std::string& w) { return is_object_pronoun(w); });
    at.topic_places = pronoun && !last_places.empty() ? last_places : context.topic_places;
    Reply reply = read_reply(grounder, world, at, quoted_words(part));
    // (A place alone reads as its own kind's part too, "start with the
    // table"; after a part, it takes that part's verb first.)
    const bool place_first = !part.empty() && !grounder.lexicon().has_verb(part.front()) &&
                             names_a_place_alone(grounder, world, part);
    if ((!usable(reply) || (i > 0 && place_first)) && !verb.empty() && !starts_with_verb(part, verb)) {
      Words with = with_verb(verb, part);
      Reply again = read_reply(grounder, world, at, quoted_words(with));
      // "floor next, then the bucket": a surface's general verb carried to
      // a receptacle is the receptacle's ("empty"), and the other way round.
      if (auto* named = std::get_if<SubtaskNamed>(&again); named && !named->places.empty()) {
        const std::string own = clearing_verb(world.universe->info(named->places.front()).kind);
        if (named->verb != own && is_one_of(named->verb, {clearing_verb(ObjectKind::kSurface), clearing_verb(ObjectKind::kReceptacle)})) {
          with = with_verb(own, part);
          again = read_reply(grounder, world, at, quoted_words(with));
        }
      }
      if (usable(again)) {
        reply = again;
        part = with;
      }
    }
    // "that's it for the desk", "done with the table": an ending about
    // the part under way, said with its place.
    // ("the counter is done. clear the floor next": a part's ending, asked
    // back when said alone at the task's next step, is here the part's.)
    if (!usable(reply) && at.asked == Asked::kTaskStep && parts.size() > 1) {
      ReplyContext part_end = at;
      part_end.asked = Asked::kSubtaskEnd;
      if (Reply ending = read_reply(grounder, world, part_end, quoted_words(part)); std::holds_alternative<Finished>(ending))
        reply = ending;
    }
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
        // (Read as a part's ending: "that's it for the bench" is asked back
        // at the task's next step, and ends a part here all the same.)
        ReplyContext part_end = at;
        part_end.asked = Asked::kSubtaskEnd;
        Reply other = read_reply(grounder, world, part_end, quoted_words(without_interjections(parts[j])));
        if (std::holds_alternative<Finished>(other)) return std::make_pair(reply, std::vector<std::string>{});
      }
    // "clear the floor, then the top of the piano": a later part about a
    // place here that does not read is kept for the next question, where
    // it is asked back; read whole, the reply would lose it silently.
    if (!step && i > 0 && first && std::holds_alternative<SubtaskNamed>(*first) && !usable(reply) &&
        names_a_place_alone(grounder, world, part) && !door_action(grounder, world, at, part)) {
      rest.push_back(quoted_words(starts_with_verb(part, verb) ? part : with_verb(verb, part)));
      continue;
    }
    if (!step) return std::nullopt;
    if (const auto* named = std::get_if<SubtaskNamed>(&reply)) {
      verb = named->verb;
      last_places = named->places;
    } else if (std::vector<ObjectId> said = places_named_alone(grounder, world, part); !usable(reply) && !said.empty()) {
      last_places = said;  // "now the buckets, empty them"
    }
    names_a_part = names_a_part || std::holds_alternative<SubtaskNamed>(reply) || std::holds_alternative<LoopNamed>(reply);
    if (i == 0) first = reply;
    // ("the floor. get all that junk off the floor": one part said twice.)
    else if (!(first && format_reply(world, *first) == format_reply(world, reply))) rest.push_back(quoted_words(part));
    // What follows the first part is read at the question about the task's
    // next step.
    at.asked = Asked::kTaskStep;
  }
  // "ok bench is done. floor next, then the bucket", asked for the task's
  // next step: the ending is the last part's, said in passing, not the
  // task's, since parts follow it; the next part comes first.
  if (context.asked == Asked::kTaskStep && first && std::holds_alternative<Finished>(*first) && names_a_part &&
      !rest.empty()) {
    first = read_reply(grounder, world, at, rest.front());
    rest.erase(rest.begin());
  }
  // "close both bins and then we're finished": a one-off action first
  // stands with an ending after it too.
  const bool action_first = first && std::holds_alternative<Command>(*first);
  if (!names_a_part && !action_first) return std::nullopt;
  // "the piano's covered in stuff. clear it off": a first part whose verb
  // names no step is a description when the reply read whole names a
  // part with a step verb.
  if (const auto* named = std::get_if<SubtaskNamed>(&*first)) {
    const auto* whole_part = std::get_if<SubtaskNamed>(&whole);
    if (!is_step_verb(named->verb, context.taught_subtasks) && whole_part != nullptr && is_step_verb(whole_part->verb))
      return std::nullopt;
  }
  return std::make_pair(*first, rest);
}

}  // namespace apprentice::language::acts
