// Which of the things offered is meant (language/reply_reading.h): "the
// one on the counter", "the first one", "the top one", "the plastic one",
// "the mug in the dish rack", "trash".
#include <algorithm>
#include <set>

#include "language/generation.h"
#include "language/reply_reading.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language {
namespace {


// The words a person may use for a choice: its name's words, its
// properties and id, and the same of where it is.
std::set<std::string> words_for(const World& world, ObjectId id) {
  std::set<std::string> out{world.universe->name(id)};
  auto add = [&](ObjectId object) {
    const ObjectInfo& info = world.universe->info(object);
    for (std::string& part : name_parts(info.category)) out.insert(std::move(part));
    for (const std::string& p : info.properties) out.insert(p);
  };
  add(id);
  if (auto where = place_of(world, id)) add(*where);
  return out;
}

bool said_for(const std::string& word, const std::set<std::string>& words) {
  if (words.count(word)) return true;
  if (word.size() > 3 && word.back() == 's' && words.count(word.substr(0, word.size() - 1))) return true;
  return false;
}

// Words that carry nothing about which one: "the one that is on the".
bool empty_word(std::string_view w) {
  return is_determiner(w) || is_copula(w) || is_filler(w) || is_generic_noun(w) ||
         is_one_of(w, {",", "that", "which", "one", "ones", "in", "on", "into", "inside", "from", "at", "of", "off",
                       "out", "i", "mean", "meant", "want", "the", "please", "by", "near", "sitting", "lying",
                       "standing", "over", "there", "here"});
}

// "neither", "no", "never mind", "skip it", "leave it": none of the things
// offered.
bool declines(const std::vector<std::string>& said) {
  std::vector<std::string> words;
  for (const std::string& w : said)
    if (w != "," && !is_filler(w)) words.push_back(w);
  if (words.empty()) return false;
  if (is_one_of(words.front(), {"neither", "none", "no", "nope", "nah", "nevermind"})) return true;
  for (std::size_t i = 0; i + 1 < words.size(); ++i) {
    const std::string& a = words[i];
    const std::string& b = words[i + 1];
    if ((a == "never" && b == "mind") || (is_one_of(a, {"forget", "skip", "leave"}) && is_one_of(b, {"it", "that", "them"})))
      return true;
  }
  return false;
}

// The choice the words name (read_which without a decline).
Reply choice_named(const ReplyInput& in) {
  const World& world = in.world;
  const std::vector<ObjectId>& choices = in.context.choices;
  if (choices.empty()) return unusable(in, Problem{"I have nothing to choose from.", std::nullopt});
  std::vector<std::string> words = in.words;
  auto has = [&](std::initializer_list<std::string_view> set) {
    return std::any_of(words.begin(), words.end(), [&](const std::string& w) { return is_one_of(w, set); });
  };
  std::string said = join(words, " ");
  if (has({"either", "whichever", "any", "matter", "care"}))
    return Chosen{choices.front()};  // the teacher says it makes no difference
  if (has({"neither", "none"}))
    return unusable(in, Problem{"Then please tell me what you meant another way.", std::nullopt});
  // "not the one in the dish rack": the words after a negation exclude.
  std::vector<std::string> content, excluded;
  bool negated = false;
  for (const std::string& w : words) {
    if (is_negation(w)) negated = true;
    else if (w == "," || w == "but") negated = false;
    else if (!empty_word(w) || in.vocabulary.is_property(w)) (negated ? excluded : content).push_back(w);
  }
  // "the first one", "the second", "the last one".
  if (content.size() <= 1) {
    constexpr std::size_t kNone = static_cast<std::size_t>(-1);
    std::string only = content.empty() ? "" : content.front();
    std::size_t index = only.empty() ? kNone : ordinal(only).value_or(kNone);
    if (index == kNone && has({"first", "former"})) index = 0;
    if (index == kNone && has({"second"})) index = 1;
    if (index == kNone && has({"third"})) index = 2;
    if (has({"last", "latter"})) index = choices.size() - 1;
    bool only_ordinal = content.empty() || ordinal(only).has_value() || only == "last" || only == "latter";
    if (index < choices.size() && only_ordinal) return Chosen{choices[index]};
  }
  if (content.empty() && excluded.empty())
    return unusable(in, Problem{"Which one? " + say_which_question(world, choices), std::nullopt});
  Resolver resolver(in);
  // The choices among `among` that a phrase names, or that are at a place
  // it names; nullopt when it names nothing here.
  auto named_among = [&](const std::vector<std::string>& phrase,
                         const std::vector<ObjectId>& among) -> std::optional<std::vector<ObjectId>> {
    if (phrase.empty()) return std::nullopt;
    auto named = resolver.candidates(Chunk::of_words(phrase), Role::kAny);
    // Places offered are named as places: "the trash can" is the garbage,
    // though "can" alone names the soda cans.
    bool offered_places = std::none_of(choices.begin(), choices.end(), [&](ObjectId id) {
      return world.universe->info(id).kind == ObjectKind::kItem;
    });
    if (!std::holds_alternative<std::vector<ObjectId>>(named) || offered_places)
      if (auto as_place = resolver.candidates(Chunk::of_words(phrase), Role::kPlace);
          std::holds_alternative<std::vector<ObjectId>>(as_place) || !offered_places)
        named = std::move(as_place);
    const auto* objects = std::get_if<std::vector<ObjectId>>(&named);
    if (!objects) return std::nullopt;
    std::vector<ObjectId> fit;
    for (ObjectId id : among) {
      auto where = place_of(world, id);
      bool is = std::find(objects->begin(), objects->end(), id) != objects->end();
      bool at = where && std::find(objects->begin(), objects->end(), *where) != objects->end();
      if (is || at) fit.push_back(id);
    }
    return fit;
  };
  // The choices a word fits, by name, property or place; a word the world
  // knows in other terms ("trash") by what it names; nullopt for a word
  // that names nothing here ("dirty"), which then says nothing about which.
  auto fitting = [&](const std::string& word, const std::vector<ObjectId>& among) -> std::optional<std::vector<ObjectId>> {
    std::vector<ObjectId> fit;
    const Lexicon& lexicon = in.grounder.lexicon();
    for (ObjectId id : among) {
      const auto& properties = world.universe->info(id).properties;
      if (said_for(word, words_for(world, id)) ||
          std::any_of(properties.begin(), properties.end(),
                      [&](const std::string& p) { return says_property(word, p, lexicon); }))
        fit.push_back(id);
    }
    if (!fit.empty()) return fit;
    return named_among({word}, among);
  };
  // The words together first: "the trash can" names the garbage as a
  // whole, though "can" alone names the soda cans.
  if (excluded.empty() && content.size() > 1) {
    std::vector<std::string> phrase;
    for (const std::string& w : content)
      if (!ordinal(w)) phrase.push_back(w);
    if (auto fit = named_among(phrase, choices); fit && fit->size() == 1) return Chosen{fit->front()};
  }
  std::vector<ObjectId> kept = choices;
  bool said_something = false;
  for (const std::string& word : excluded) {
    auto fit = fitting(word, kept);
    if (!fit) continue;
    said_something = true;
    std::erase_if(kept, [&](ObjectId id) { return std::find(fit->begin(), fit->end(), id) != fit->end(); });
  }
  for (const std::string& word : content) {
    auto fit = fitting(word, kept);
    if (!fit) continue;
    said_something = true;
    if (fit->empty())
      return unusable(in, Problem{"None of them is \"" + said + "\". " + say_which_question(world, choices),
                                  std::nullopt});
    kept = std::move(*fit);
  }
  if (!said_something || kept.empty())
    return unusable(in, Problem{"I can't tell which one \"" + said + "\" is. " + say_which_question(world, choices),
                                std::nullopt});
  if (kept.size() == 1) return Chosen{kept.front()};
  return Ambiguous{join(content, " "), kept, say_which_question(world, kept)};
}

}  // namespace

Reply read_which(const ReplyInput& in) {
  Reply chosen = choice_named(in);
  if (std::holds_alternative<Chosen>(chosen) || std::holds_alternative<Ambiguous>(chosen)) return chosen;
  // Declining every choice is a "no": the caller sets aside what the
  // question came from.
  if (declines(in.words)) return YesNo{false};
  return chosen;
}

}  // namespace apprentice::language
