// Yes and no in everyday English (language/reply_reading.h): "yep",
// "that's right", "no, the other one" (the rest is kept for the agent).
#include <algorithm>

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
      {"bingo"}, {"you", "are", "right"}, {"right", "on"}, {"please", "go", "ahead"}, {"that", "is", "what", "i", "want"}};
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

}  // namespace

std::optional<bool> yes_or_no(std::string_view text) {
  auto answer = answer_prefix(without_lead(reply_words(text)));
  if (!answer) return std::nullopt;
  return answer->second;
}

Reply read_yes_no(const ReplyInput& in) {
  Words words = without_lead(in.words);
  auto answer = answer_prefix(words);
  if (!answer)
    return unusable(in, Problem{"Please answer yes or no.", std::nullopt});
  Words rest(words.begin() + static_cast<std::ptrdiff_t>(answer->first), words.end());
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
    if (const auto* given = std::get_if<GoalGiven>(&said); given && given->others.empty()) {
      const std::vector<Literal>& proposed = in.context.proposal->literals;
      bool within = std::all_of(given->goal.literals.begin(), given->goal.literals.end(), [&](const Literal& l) {
        return std::find(proposed.begin(), proposed.end(), l) != proposed.end();
      });
      if (within) reply.rest.clear();
    }
  }
  return reply;
}

}  // namespace apprentice::language
