#include "language/known_verbs.h"

#include <algorithm>
#include <array>
#include <tuple>

#include "util/text.h"

namespace apprentice::language {
namespace {

// A known verb, with the WordNet senses (numbered from 1, as WordNet
// orders them) the agent means by it, and the kind of place a step verb is
// for.
struct KnownVerb {
  std::string_view verb;
  std::array<int, 2> senses;  // 0: none
  ObjectKind place;
};

// "tidy, tidy up, clean up, neaten, straighten, straighten out".
constexpr std::array<KnownVerb, 1> kTaskVerbs{{{"tidy", {1, 0}, ObjectKind::kItem}}};
// clear 1 "unclutter" and 5 "remove from"; empty 1 "make empty" and 4
// "remove the contents"; store 1 and 2 "keep in a place"; unload 2
// "unload, unlade, offload".
constexpr std::array<KnownVerb, 4> kStepVerbs{{{"clear", {1, 5}, ObjectKind::kSurface},
                                               {"empty", {1, 4}, ObjectKind::kReceptacle},
                                               {"store", {1, 2}, ObjectKind::kSurface},
                                               {"unload", {2, 0}, ObjectKind::kReceptacle}}};

// How many of the teacher's verb's senses, commonest first, are compared:
// rarer senses ("clean" as "to win all the money") would make every verb
// close to something.
constexpr std::size_t kTeacherSenses = 4;
// Verbs beside each other under a hypernym are close only when that
// hypernym is not one of WordNet's most general verbs: "remove, take
// away" (112 kinds) joins "unpack" and "empty"; "change, alter" (401)
// would join "empty" with "paint".
constexpr std::size_t kMaxKindsOfSharedHypernym = 150;

bool contains(const std::vector<SynsetOffset>& offsets, SynsetOffset offset) {
  return std::find(offsets.begin(), offsets.end(), offset) != offsets.end();
}

// Whether `above` is a hypernym of few enough kinds to join the verbs
// under it (kMaxKindsOfSharedHypernym).
bool small_hypernym(const WordNet& wordnet, SynsetOffset above) {
  auto shared = wordnet.verb_synset(above);
  return shared && shared->hyponyms.size() <= kMaxKindsOfSharedHypernym;
}

// How far apart two verb synsets are by WordNet's links: 0 the same, 1
// one directly above the other or in one verb group, 2 beside each other
// under a hypernym of at most kMaxKindsOfSharedHypernym kinds, 3 the
// teacher's beside the known one's hypernym under such a hypernym
// ("organize, coordinate" and "order", which is above "tidy", are both
// kinds of "arrange"); nullopt otherwise.
std::optional<int> linked_distance(const WordNet& wordnet, SynsetOffset said, SynsetOffset known) {
  if (said == known) return 0;
  auto a = wordnet.verb_synset(said);
  auto b = wordnet.verb_synset(known);
  if (!a || !b) return std::nullopt;
  if (contains(a->hypernyms, known) || contains(b->hypernyms, said) || contains(a->groups, known) ||
      contains(b->groups, said))
    return 1;
  for (SynsetOffset above : a->hypernyms)
    if (contains(b->hypernyms, above) && small_hypernym(wordnet, above)) return 2;
  for (SynsetOffset known_above : b->hypernyms) {
    auto parent = wordnet.verb_synset(known_above);
    if (!parent) continue;
    for (SynsetOffset above : a->hypernyms)
      if (contains(parent->hypernyms, above) && small_hypernym(wordnet, above)) return 3;
  }
  return std::nullopt;
}

// The verbs a WordNet definition is headed by, its genus: "arrange or
// order by classes or categories" (classify, sort out) is headed by
// "arrange" and "order". The words up to the first that is not a verb,
// "or" or "and".
std::vector<std::string> genus_verbs(const WordNet& wordnet, const std::string& gloss) {
  std::vector<std::string> out;
  for (const std::string& word : split_words(gloss)) {
    if (word == "or" || word == "and") continue;
    if (!wordnet.has_verb(word)) break;
    out.push_back(word);
  }
  return out;
}

// How far apart two verb synsets are: by WordNet's links (linked_distance),
// else through the teacher's sense's definition. A verb defined as a kind
// of another ("sort out: arrange or order by classes") is one step below
// the verb that heads its definition, where WordNet draws no link: 3 when
// a sense of a heading verb is the known sense or directly above it
// ("order: bring order to or into" is above "tidy").
std::optional<int> distance(const WordNet& wordnet, SynsetOffset said, SynsetOffset known) {
  if (auto linked = linked_distance(wordnet, said, known)) return linked;
  auto a = wordnet.verb_synset(said);
  auto b = wordnet.verb_synset(known);
  if (!a || !b) return std::nullopt;
  for (const std::string& head : genus_verbs(wordnet, a->gloss))
    for (SynsetOffset sense : wordnet.verb_senses(head))
      if (sense == known || contains(b->hypernyms, sense)) return 3;
  return std::nullopt;
}

// Particles that mark an act as done through ("tidy up", "clean up",
// "straighten up", "sort out") and leave the verb's meaning as it is in
// everyday use: where WordNet keeps the verb with such a particle only in
// another sense ("straighten up": straighten oneself), the verb alone is
// compared as well. A rule over the particles, not over verbs: other
// particles change the meaning ("put away" is not "put"), so they are not
// dropped.
bool completive_particle(std::string_view particle) { return particle == "up" || particle == "out"; }


// The WordNet lemma of a verb as said: "clean up" when WordNet has it,
// else the verb alone.
std::string lemma_of(const WordNet& wordnet, std::string_view verb, std::string_view particle) {
  if (!particle.empty()) {
    std::string phrasal = std::string(verb) + " " + std::string(particle);
    if (wordnet.has_verb(phrasal)) return phrasal;
  }
  return std::string(verb);
}

// The known verb nearest to the senses of `lemma`, or nullptr.
template <std::size_t N>
const KnownVerb* nearest_to_lemma(const WordNet* wordnet, const std::string& lemma,
                                  const std::array<KnownVerb, N>& known, std::optional<ObjectKind> place) {
  std::vector<SynsetOffset> said = wordnet->verb_senses(lemma);
  if (said.size() > kTeacherSenses) said.resize(kTeacherSenses);
  // The closest, then the commoner sense of the teacher's verb, then the
  // verb for this kind of place.
  std::optional<std::tuple<int, std::size_t, bool>> best;
  const KnownVerb* chosen = nullptr;
  for (const KnownVerb& k : known) {
    std::vector<SynsetOffset> senses = wordnet->verb_senses(k.verb);
    for (int number : k.senses) {
      if (number <= 0 || static_cast<std::size_t>(number) > senses.size()) continue;
      for (std::size_t rank = 0; rank < said.size(); ++rank) {
        auto d = distance(*wordnet, said[rank], senses[static_cast<std::size_t>(number - 1)]);
        if (!d) continue;
        std::tuple<int, std::size_t, bool> key{*d, rank, !(place && k.place == *place)};
        if (!best || key < *best) {
          best = key;
          chosen = &k;
        }
      }
    }
  }
  return chosen;
}

template <std::size_t N>
std::optional<VerbTaken> nearest(const Lexicon& lexicon, std::string_view verb, std::string_view particle,
                                 const std::array<KnownVerb, N>& known, std::optional<ObjectKind> place) {
  const WordNet* wordnet = lexicon.wordnet();
  if (wordnet == nullptr || verb.empty()) return std::nullopt;
  std::string lemma = lemma_of(*wordnet, verb, particle);
  if (!wordnet->has_verb(lemma))
    if (std::string other = reversative_lemma(lexicon, lemma); !other.empty()) lemma = other;
  const KnownVerb* chosen = nearest_to_lemma(wordnet, lemma, known, place);
  if (chosen == nullptr && lemma.find(' ') != std::string::npos && completive_particle(particle))
    chosen = nearest_to_lemma(wordnet, std::string(verb), known, place);
  if (chosen == nullptr) return std::nullopt;
  std::string as_said = particle.empty() ? std::string(verb) : std::string(verb) + " " + std::string(particle);
  return VerbTaken{std::string(chosen->verb), "I took " + apprentice::quoted(as_said) + " as " + ing_form(chosen->verb) + "."};
}

template <std::size_t N>
bool is_known(std::string_view verb, const std::array<KnownVerb, N>& known) {
  return std::any_of(known.begin(), known.end(), [&](const KnownVerb& k) { return k.verb == verb; });
}

}  // namespace

std::string reversative_lemma(const Lexicon& lexicon, std::string_view verb) {
  static constexpr std::array<std::string_view, 3> kPrefixes = {"de", "un", "dis"};
  if (lexicon.has_verb(verb)) return "";
  for (std::string_view prefix : kPrefixes) {
    if (!verb.starts_with(prefix) || verb.size() < prefix.size() + 3) continue;
    std::string_view stem = verb.substr(prefix.size());
    for (std::string_view other : kPrefixes) {
      std::string lemma = std::string(other) + std::string(stem);
      if (other != prefix && lexicon.has_verb(lemma)) return lemma;
    }
  }
  return "";
}

std::optional<VerbTaken> known_task_verb(const Lexicon& lexicon, std::string_view verb, std::string_view particle) {
  if (is_known(verb, kTaskVerbs)) return std::nullopt;
  return nearest(lexicon, verb, particle, kTaskVerbs, std::nullopt);
}

std::optional<VerbTaken> task_verb_over_everything(std::string_view verb, std::string_view particle) {
  if (is_known(verb, kTaskVerbs)) return std::nullopt;
  const KnownVerb& tidy = kTaskVerbs.front();
  std::string as_said = particle.empty() ? std::string(verb) : std::string(verb) + " " + std::string(particle);
  return VerbTaken{std::string(tidy.verb),
                   "I took " + apprentice::quoted(as_said) + " said of everything here as " + ing_form(tidy.verb) + "."};
}

bool names_a_known_task(const Lexicon& lexicon, std::string_view verb, std::string_view particle) {
  return is_known(verb, kTaskVerbs) || known_task_verb(lexicon, verb, particle).has_value();
}

std::string task_name_as_read(const Lexicon& lexicon, std::string_view name) {
  const std::vector<std::string> words = split_words(name);
  if (words.size() < 2) return std::string(name);
  // "clean up garage": the particle is said with the verb, and dropped.
  const bool particle = words.size() > 2 && (words[1] == "up" || words[1] == "out");
  auto taken = known_task_verb(lexicon, words[0], particle ? words[1] : std::string());
  if (!taken) return std::string(name);
  std::string out = taken->verb;
  for (std::size_t i = particle ? 2 : 1; i < words.size(); ++i) out += " " + words[i];
  return out;
}

std::optional<VerbTaken> known_step_verb(const Lexicon& lexicon, std::string_view verb, std::string_view particle,
                                         ObjectKind place, std::span<const std::string> taught) {
  std::string as_said = particle.empty() ? std::string(verb) : std::string(verb) + " " + std::string(particle);
  if (is_known(as_said, kStepVerbs) || std::find(taught.begin(), taught.end(), as_said) != taught.end())
    return std::nullopt;
  return nearest(lexicon, verb, particle, kStepVerbs, place);
}

bool is_step_verb(std::string_view verb, std::span<const std::string> taught) {
  return is_known(verb, kStepVerbs) || std::find(taught.begin(), taught.end(), verb) != taught.end();
}

std::string clearing_verb(ObjectKind place) { return place == ObjectKind::kSurface ? "clear" : "empty"; }

std::string ing_form(std::string_view verb) {
  std::string out(verb);
  if (out.size() > 2 && out.back() == 'e' && out[out.size() - 2] != 'e') out.pop_back();  // store -> storing
  return out + "ing";
}

}  // namespace apprentice::language
