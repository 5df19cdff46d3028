// Yes and no in everyday English (language/reply_reading.h): "yep",
// "that's right", "no, the other one" (the rest is kept for the agent).
#include <algorithm>

#include "language/narration.h"
#include "language/reply_acts_parts.h"
#include "language/reply_reading.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language {
namespace {

using Words = std::vector<std::string>;

const std::vector<std::vector<std::string_view>>& yes_phrases() {
  static const std::vector<std::vector<std::string_view>> kYes{
      {"yes"}, {"y"}, {"yeah"}, {"yea"}, {"yep"}, {"yup"}, {"ya"}, {"sure"}, {"correct"}, {"right"},
      {"exactly"}, {"absolutely"}, {"definitely"}, {"indeed"}, {"of", "course"}, {"ok"}, {"sounds", "good"},
      {"sounds", "right"}, {"that", "works"}, {"go", "ahead"}, {"do", "it"}, {"please", "do"}, {"affirmative"},
      {"mhm"}, {"uh", "huh"}, {"you", "got", "it"}, {"perfect"}, {"good"}, {"great"}, {"fine"}, {"true"},
      {"certainly"}, {"totally"}, {"you", "bet"}, {"i", "think", "so"}, {"looks", "good"}, {"looks", "right"},
      {"agreed"}, {"precisely"}, {"alright"}, {"that", "is", "right"}, {"that", "is", "correct"},
      {"that", "is", "it"}, {"that", "is", "true"}, {"that", "is", "the", "one"}, {"it", "is"}, {"it", "does"},
      {"sure", "thing"}, {"yes", "please"}, {"please"}, {"why", "not"}, {"that", "one"}, {"correct", "answer"},
      {"that", "is", "fine"}, {"that", "is", "good"}, {"very", "good"}, {"spot", "on"}, {"go", "for", "it"},
      {"do", "that"}, {"that", "will", "do"}, {"i", "agree"}, {"makes", "sense"}, {"that", "makes", "sense"},
      {"bingo"}, {"obviously"}, {"of", "course"}, {"you", "are", "right"}, {"right", "on"}, {"please", "go", "ahead"}, {"that", "is", "what", "i", "want"}};
  return kYes;
}

const std::vector<std::vector<std::string_view>>& no_phrases() {
  static const std::vector<std::vector<std::string_view>> kNo{
      {"no"}, {"n"}, {"nope"}, {"nah"}, {"nay"}, {"not", "quite"}, {"not", "really"}, {"wrong"},
      {"that", "is", "wrong"}, {"that", "is", "not", "right"}, {"that", "is", "not", "it"}, {"not", "right"},
      {"incorrect"}, {"that", "is", "incorrect"}, {"no", "way"}, {"negative"}, {"do", "not"}, {"please", "do", "not"},
      {"absolutely", "not"}, {"definitely", "not"}, {"of", "course", "not"}, {"i", "do", "not", "think", "so"},
      {"not", "at", "all"}, {"not", "exactly"}, {"not", "that"}, {"never"}, {"no", "thanks"}, {"false"},
      {"that", "is", "false"}, {"it", "is", "not"}, {"it", "does", "not"}, {"not", "that", "one"}, {"wrong", "one"},
      {"not", "correct"}, {"that", "is", "not", "correct"}, {"not", "at", "all"}, {"no", "thank", "you"},
      {"that", "is", "not", "what", "i", "meant"}, {"not", "this", "one"}, {"hardly"}};
  return kNo;
}

}  // namespace

std::optional<std::pair<std::size_t, bool>> answer_prefix(const std::vector<std::string>& words) {
  std::optional<std::pair<std::size_t, bool>> best;
  for (bool yes : {true, false})
    for (const auto& phrase : yes ? yes_phrases() : no_phrases())
      if (phrase.size() <= words.size() && std::equal(phrase.begin(), phrase.end(), words.begin()) &&
          (!best || phrase.size() > best->first))
        best = std::pair{phrase.size(), yes};
  return best;
}

namespace {

// Whether words only repeat an answer or thank: "exactly", "that's right", "thanks".
bool only_confirms(Words words) {
  while (!words.empty()) {
    if (words.front() == "," ||
        is_one_of(words.front(), {"thanks", "thank", "you", "please", "ok", "so", "then", "place", "spot", "one",
                                  "answer", "guess", "idea", "choice", "sir", "maam", "boss", "mate", "buddy"})) {
      words.erase(words.begin());
      continue;
    }
    auto answer = answer_prefix(words);
    if (!answer) return false;
    words.erase(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(answer->first));
  }
  return true;
}

}  // namespace

namespace {

Words without_lead(Words words) {
  while (!words.empty() && is_one_of(words.front(), {"oh", "well", "um", "uh", "hmm", ",", "so"}))
    words.erase(words.begin());
  return words;
}

// The words from the first yes or no on, after words that carry nothing
// before it: interjections and words no dictionary knows ("lol no", "mm
// not really", "ugh, yes"). At most three are passed over; a known word
// ("not sure", "I don't know") is never, so no answer is made up.
Words from_the_answer(const Words& said, const Lexicon& lexicon) {
  constexpr std::size_t kMostPassedOver = 3;
  std::size_t passed = 0;
  for (std::size_t i = 0; i < said.size() && passed <= kMostPassedOver; ++i) {
    Words rest(said.begin() + static_cast<std::ptrdiff_t>(i), said.end());
    if (answer_prefix(rest)) return rest;
    const std::string& w = said[i];
    if (w == ",") continue;
    if (!acts::is_interjection(w) && !(lexicon.has_wordnet() && !lexicon.knows(w))) break;
    ++passed;
  }
  return said;
}

// Whether a goal said holds only what was proposed ("sure, same place",
// "the ketchup goes in the fridge" to the fridge proposed).
bool holds_only_the_proposal(const GoalGiven& given, const Goal& proposal) {
  const std::vector<Literal>& proposed = proposal.literals;
  return given.others.empty() && std::all_of(given.goal.literals.begin(), given.goal.literals.end(), [&](const Literal& l) {
           return std::find(proposed.begin(), proposed.end(), l) != proposed.end();
         });
}

// A reply to a proposed goal that says, in place of yes or no, where the
// thing goes ("hang on, the jumper goes in the wardrobe") or that the part
// is over ("I'm done"): read as at the question where the thing goes,
// after any marker or filler before it. A goal the proposal holds is a
// yes; another is a no with the goal as the rest, read as "no, the jumper
// goes in the wardrobe" is. nullopt when it says neither.
std::optional<Reply> said_instead_of_yes_or_no(const ReplyInput& in, Words words) {
  if (!in.context.object || !in.context.proposal) return std::nullopt;
  const acts::Marker lead = acts::marker(words);
  if (lead.length < words.size()) words.erase(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(lead.length));
  while (!words.empty() && (words.front() == "," || acts::is_interjection(words.front()))) words.erase(words.begin());
  if (words.empty()) return std::nullopt;
  ReplyContext at = in.context;
  at.asked = Asked::kGoal;
  const std::string text = join(words, " ");
  Reply said = read_reply(in.grounder, in.world, at, text);
  if (std::holds_alternative<Finished>(said)) return said;
  const auto* given = std::get_if<GoalGiven>(&said);
  if (given == nullptr) return std::nullopt;
  const std::vector<ObjectId> mentioned = given->goal.objects();
  if (std::find(mentioned.begin(), mentioned.end(), *in.context.object) == mentioned.end()) return std::nullopt;
  if (holds_only_the_proposal(*given, *in.context.proposal)) return YesNo{true, ""};
  return YesNo{false, text};
}

std::optional<bool> yes_or_no_of(const Words& words) {
  auto answer = answer_prefix(words);
  if (!answer) answer = answer_prefix(without_lead(words));
  if (!answer) return std::nullopt;
  return answer->second;
}

}  // namespace

std::optional<bool> yes_or_no(std::string_view text) { return yes_or_no_of(reply_words(text)); }

Reply read_yes_no(const ReplyInput& in) {
  // "uh huh" is an answer before "uh" is a filler.
  Words words = answer_prefix(in.words) ? in.words : without_lead(in.words);
  auto answer = answer_prefix(words);
  if (!answer) {
    words = from_the_answer(in.words, in.grounder.lexicon());
    answer = answer_prefix(words);
  }
  if (!answer) {
    if (auto instead = said_instead_of_yes_or_no(in, in.words)) return *instead;
    return unusable(in, Problem{"Please answer yes or no.", std::nullopt});
  }
  Words rest(words.begin() + static_cast<std::ptrdiff_t>(answer->first), words.end());
  // "ok I'm done", "right, the ketchup goes in the pantry": a yes said
  // with a word that is also a filler is that filler when what follows
  // ends the part or says another goal.
  const bool filler_yes =
      answer->second && std::all_of(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(answer->first),
                                    [](const std::string& w) { return acts::is_interjection(w); });
  // ("yeah that's right": a rest that only confirms is no other goal.)
  if (filler_yes && !rest.empty() && !only_confirms(rest)) {
    std::optional<Reply> instead = said_instead_of_yes_or_no(in, rest);
    const auto* yes_no = instead ? std::get_if<YesNo>(&*instead) : nullptr;
    if (instead && (yes_no == nullptr || !yes_no->yes)) return *instead;
  }
  YesNo reply{answer->second, ""};
  if (!only_confirms(rest)) {
    while (!rest.empty() && is_one_of(rest.front(), {",", "but", "and", "so", "then", "just", "though"}))
      rest.erase(rest.begin());
    reply.rest = join(rest, " ");
  }
  // "sure, same place", "yes, in the cupboard": a rest that says only what
  // was proposed adds nothing to the yes.
  if (reply.yes && !reply.rest.empty() && in.context.proposal && in.context.object) {
    ReplyContext at = in.context;
    at.asked = Asked::kGoal;
    Reply said = read_reply(in.grounder, in.world, at, reply.rest);
    if (const auto* given = std::get_if<GoalGiven>(&said); given && holds_only_the_proposal(*given, *in.context.proposal))
      reply.rest.clear();
  }
  return reply;
}

std::optional<GoalGiven> goal_in_rest(const Grounder& grounder, const World& world, const ReplyContext& context,
                                      const YesNo& answer) {
  if (answer.rest.empty() || !context.object) return std::nullopt;
  ReplyContext at = context;
  at.asked = Asked::kGoal;
  // "yes. spray bottle in there too": after a yes, "there" is the place
  // proposed, not the one named before the question, and "too" is the goal
  // proposed.
  if (answer.yes && context.proposal) {
    if (auto proposed = acts::destination(world, GoalGiven{*context.proposal, {}})) at.recent_place = proposed;
    at.last_goal = ReplyContext::LastGoal{*context.object, *context.proposal};
  }
  // "yeah, and envelopes as well", "no, top drawer. ruler and calculator
  // too": the things said too get the same goal as the one asked about.
  if (auto [before, toos] = acts::without_trailing_toos(answer.rest); !toos.empty()) {
    std::optional<GoalGiven> first;
    YesNo shorter = answer;
    shorter.rest = before;
    if (!trim(before).empty()) first = goal_in_rest(grounder, world, context, shorter);
    if (!first && answer.yes && context.proposal) first = GoalGiven{*context.proposal, {}};
    if (first) {
      acts::add_the_same_for(grounder, world, at, toos, *first);
      if (!first->others.empty()) return first;
    }
  }
  auto only_proposed = [&](const GoalGiven& given) {
    return context.proposal && holds_only_the_proposal(given, *context.proposal);
  };
  const Reply said = read_reply(grounder, world, at, answer.rest);
  if (const auto* given = std::get_if<GoalGiven>(&said)) {
    if (only_proposed(*given)) return std::nullopt;
    return *given;
  }
  // "yes but leave the door open", "sure, and shut it": the place proposed,
  // with what the rest says of its door.
  if (!answer.yes || !context.proposal) return std::nullopt;
  const std::optional<ObjectId> place = acts::destination(world, GoalGiven{*context.proposal, {}});
  if (!place) return std::nullopt;
  const std::string there = std::string(relation_word(world, *place)) + " " + spoken_name(world, *place);
  const Reply with_door = read_reply(grounder, world, at, there + ", " + answer.rest);
  // Only a goal that says more of the place than was proposed (its door):
  // the proposal with that.
  const auto* given = std::get_if<GoalGiven>(&with_door);
  if (given == nullptr || acts::destination(world, with_door) != place) return std::nullopt;
  auto of_the_place = [&](const Literal& l) { return l.fact.arity == 1 && l.fact.args[0] == *place; };
  std::vector<Literal> literals = context.proposal->literals;
  bool more = false;
  for (const Literal& l : given->goal.literals) {
    if (!of_the_place(l) || std::find(literals.begin(), literals.end(), l) != literals.end()) continue;
    // "leave it open" over a proposal that closes it: the person's word.
    std::erase_if(literals, [&](const Literal& p) { return of_the_place(p) && p.fact.predicate == l.fact.predicate; });
    literals.push_back(l);
    more = true;
  }
  if (!more) return std::nullopt;
  return GoalGiven{Goal(std::move(literals)), {}};
}

}  // namespace apprentice::language
