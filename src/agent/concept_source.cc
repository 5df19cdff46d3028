#include "agent/concept_source.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <set>

#include "util/text.h"

namespace apprentice {

namespace {

// WordNet's lexicographer files of things one can hold or put away: made
// things, food, substances and natural objects first, then plants and
// animals ("mango" is first a tree in WordNet, then the fruit; a "stuffed
// sheep" is named by the animal). 0 for any other sense.
int physical_rank(int lexicographer_file) {
  switch (lexicographer_file) {
    case 6:   // noun.artifact
    case 13:  // noun.food
    case 17:  // noun.object
    case 27:  // noun.substance
      return 2;
    case 5:   // noun.animal
    case 20:  // noun.plant
      return 1;
    default: return 0;
  }
}

// A sense's rank: its lexicographer file's, else that of a parent ranked
// 2: WordNet files a notebook (a book with blank pages, under "book,
// volume") among communication, yet one holds and shelves it.
int sense_rank(const language::WordNet& wordnet, language::SynsetOffset sense) {
  auto s = wordnet.synset(sense);
  if (!s) return 0;
  if (int rank = physical_rank(s->lexicographer_file); rank > 0) return rank;
  for (language::SynsetOffset parent : s->hypernyms)
    if (auto p = wordnet.synset(parent); p && physical_rank(p->lexicographer_file) == 2) return 2;
  return 0;
}

// A class word's synset holding at most this many synsets (itself
// included) is a collective name for its parent's things.
constexpr double kCollectiveSize = 5;

// The weights of a word's senses, most frequent first.
constexpr double kSenseWeights[] = {1.0, 0.5, 0.25};
// The senses of the base forms of a lemma's last word ("potato chips" ->
// "potato chip"), added to `offsets` where they are not in it already.
// WordNet's morphology of a whole collocation tries every word and is slow.
void add_base_form_senses(const language::WordNet& wordnet, const std::string& lemma,
                          std::vector<language::SynsetOffset>& offsets) {
  const std::size_t space = lemma.rfind(' ');
  const std::string before = space == std::string::npos ? "" : lemma.substr(0, space + 1);
  for (const std::string& base : wordnet.noun_base_forms(space == std::string::npos ? lemma : lemma.substr(space + 1)))
    for (language::SynsetOffset o : wordnet.noun_senses(before + base))
      if (std::find(offsets.begin(), offsets.end(), o) == offsets.end()) offsets.push_back(o);
}

// The weight of a class word's senses beyond those senses() chooses.
constexpr double kOtherSenseWeight = 0.25;

bool is_article(std::string_view word) { return word == "the" || word == "a" || word == "an"; }

std::string concept_id(language::SynsetOffset offset) {
  char text[32];
  std::snprintf(text, sizeof text, "wordnet:%08ld", offset);
  return text;
}

}  // namespace

std::vector<std::string> name_words(std::string_view name, const std::function<bool(std::string_view)>& known) {
  std::string text = to_lower(name);
  // "Rubik's cube" -> "rubik cube"; the typographic apostrophe too.
  for (std::string_view possessive : {"'s", "\xE2\x80\x99s"})
    for (std::size_t at = text.find(possessive); at != std::string::npos; at = text.find(possessive, at))
      text.erase(at, possessive.size());
  for (char& c : text)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-') c = ' ';
  std::vector<std::string> out;
  for (const std::string& token : split_words(text)) {
    if (std::all_of(token.begin(), token.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
      continue;  // "decorative pillow 2"
    if (token.find('-') == std::string::npos || (known && known(token))) {
      out.push_back(token);
      continue;
    }
    std::string part;
    for (char c : token + "-") {
      if (c != '-') {
        part += c;
      } else if (!part.empty()) {
        out.push_back(part);
        part.clear();
      }
    }
  }
  return out;
}

LexicalConcepts::LexicalConcepts(const language::Lexicon& lexicon, const vectors::WordVectors* vectors)
    : lexicon_(&lexicon), vectors_(vectors) {}

bool LexicalConcepts::known_word(std::string_view word) const {
  const language::WordNet* wordnet = lexicon_->wordnet();
  if (wordnet != nullptr && wordnet->has_noun(word)) return true;
  // A hyphenated word WordNet knows as words apart ("ice-cream": "ice
  // cream") is read as those words, whatever odd token the vectors hold.
  if (wordnet != nullptr && word.find('-') != std::string_view::npos) {
    std::string spaced(word);
    std::replace(spaced.begin(), spaced.end(), '-', ' ');
    if (wordnet->has_noun(spaced)) return false;
  }
  return vectors_ != nullptr && vectors_->contains(word);
}

std::vector<std::pair<language::SynsetOffset, double>> LexicalConcepts::senses(const std::string& lemma) const {
  std::vector<std::pair<language::SynsetOffset, double>> out;
  const language::WordNet* wordnet = lexicon_->wordnet();
  if (wordnet == nullptr) return out;
  std::vector<language::SynsetOffset> offsets = wordnet->noun_senses(lemma);
  auto names_a_physical_thing = [&](language::SynsetOffset o) { return sense_rank(*wordnet, o) > 0; };
  // Else by the base form of its last word. A plural WordNet knows only as
  // something else also gets its singular's senses: "shoes" is a situation
  // ("in her shoes") as a word of its own, and footwear as a shoe;
  // "clothes", apparel, keeps its own.
  if (offsets.empty() || std::none_of(offsets.begin(), offsets.end(), names_a_physical_thing))
    add_base_form_senses(*wordnet, lemma, offsets);
  std::vector<int> ranks;
  for (language::SynsetOffset o : offsets) ranks.push_back(sense_rank(*wordnet, o));
  std::vector<language::SynsetOffset> physical;
  for (int rank : {2, 1})
    for (std::size_t i = 0; i < offsets.size(); ++i)
      if (ranks[i] == rank) physical.push_back(offsets[i]);
  const std::vector<language::SynsetOffset>& chosen = physical.empty() ? offsets : physical;
  for (std::size_t i = 0; i < chosen.size() && i < std::size(kSenseWeights); ++i) out.emplace_back(chosen[i], kSenseWeights[i]);
  return out;
}

double LexicalConcepts::class_size(language::SynsetOffset offset) const {
  const language::WordNet* wordnet = lexicon_->wordnet();
  return wordnet ? std::max(wordnet->class_size(offset), 1) : 1.0;
}

std::string LexicalConcepts::class_name(language::SynsetOffset offset) const {
  const language::WordNet* wordnet = lexicon_->wordnet();
  auto s = wordnet ? wordnet->synset(offset) : std::nullopt;
  return s && !s->lemmas.empty() ? s->lemmas.front() : concept_id(offset);
}

std::vector<ConceptClass> LexicalConcepts::classes_above(
    const std::vector<std::pair<language::SynsetOffset, double>>& senses) const {
  const language::WordNet* wordnet = lexicon_->wordnet();
  std::map<language::SynsetOffset, ConceptClass> found;
  std::vector<language::SynsetOffset> order;
  for (const auto& [sense, weight] : senses) {
    std::vector<language::SynsetOffset> frontier{sense};
    std::set<language::SynsetOffset> visited;
    for (int depth = 0; !frontier.empty() && depth < 32; ++depth) {
      std::vector<language::SynsetOffset> next;
      for (language::SynsetOffset o : frontier) {
        if (!visited.insert(o).second) continue;
        auto [it, fresh] = found.try_emplace(o);
        ConceptClass& c = it->second;
        if (fresh) {
          c = ConceptClass{concept_id(o), class_name(o), weight, class_size(o), depth};
          order.push_back(o);
        } else {
          c.weight = std::max(c.weight, weight);
          c.depth = std::min(c.depth, depth);
        }
        if (auto s = wordnet ? wordnet->synset(o) : std::nullopt)
          next.insert(next.end(), s->hypernyms.begin(), s->hypernyms.end());
      }
      frontier = std::move(next);
    }
  }
  std::vector<ConceptClass> out;
  for (language::SynsetOffset o : order) out.push_back(found.at(o));
  std::stable_sort(out.begin(), out.end(), [](const ConceptClass& a, const ConceptClass& b) {
    if (a.depth != b.depth) return a.depth < b.depth;
    return a.weight > b.weight;
  });
  return out;
}

std::vector<float> LexicalConcepts::words_vector(const std::vector<std::string>& words,
                                                 const std::vector<double>& weights) const {
  if (vectors_ == nullptr || words.empty()) return {};
  return vectors_->phrase(words, weights);
}

KindProfile LexicalConcepts::profile(std::string_view kind) const {
  if (auto cached = profiles_.find(kind); cached != profiles_.end()) return cached->second;
  KindProfile p;
  p.kind = std::string(kind);
  std::vector<std::string> words = name_words(kind, [this](std::string_view w) { return known_word(w); });
  while (words.size() > 1 && is_article(words.front())) words.erase(words.begin());
  // "case of canned tuna": what the container holds names the thing.
  std::vector<std::string> container;
  if (auto of = std::find(words.begin(), words.end(), "of"); of != words.end() && of != words.begin() && of + 1 != words.end()) {
    container.assign(words.begin(), of);
    words.erase(words.begin(), of + 1);
  }
  std::vector<std::string> head_words;
  std::vector<std::pair<language::SynsetOffset, double>> head_senses;
  for (std::size_t k = 0; k < words.size() && head_senses.empty(); ++k) {
    std::vector<std::string> ending(words.begin() + static_cast<std::ptrdiff_t>(k), words.end());
    head_senses = senses(join(ending, " "));
    if (!head_senses.empty()) {
      head_words = ending;
      p.modifiers.assign(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(k));
    }
  }
  if (head_words.empty() && !words.empty()) {
    head_words = {words.back()};
    p.modifiers.assign(words.begin(), words.end() - 1);
  }
  p.modifiers.insert(p.modifiers.begin(), container.begin(), container.end());
  std::erase_if(p.modifiers, [](const std::string& m) { return is_article(m) || m == "and" || m == "with"; });
  p.head = join(head_words, " ");
  p.classes = classes_above(head_senses);
  std::vector<std::string> all = p.modifiers;
  all.insert(all.end(), head_words.begin(), head_words.end());
  std::vector<double> weights(all.size(), 1.0);
  if (!weights.empty()) weights.back() = 2.0;
  p.vector = words_vector(all, weights);
  p.head_vector = words_vector(head_words, std::vector<double>(head_words.size(), 1.0));
  p.modifier_vector = words_vector(p.modifiers, std::vector<double>(p.modifiers.size(), 1.0));
  if (vectors_ != nullptr)
    for (const std::string& word : all)
      if (std::vector<float> v = vectors_->word(word); !v.empty()) p.word_vectors.push_back(std::move(v));
  return profiles_.emplace(std::string(kind), std::move(p)).first->second;
}

std::vector<ConceptClass> LexicalConcepts::classes_named(std::string_view words) const {
  std::vector<ConceptClass> out;
  std::vector<std::string> said = name_words(words, [this](std::string_view w) { return known_word(w); });
  const language::WordNet* wordnet = lexicon_->wordnet();
  const std::string phrase = join(said, " ");
  // The senses of the words as said, not of a singular they are the plural
  // of: "clothes" is a word of its own, "pots" the plural of "pot".
  const std::vector<language::SynsetOffset> as_said =
      wordnet != nullptr ? wordnet->noun_senses(phrase) : std::vector<language::SynsetOffset>{};
  for (const auto& [sense, weight] : senses(phrase)) {
    out.push_back(ConceptClass{concept_id(sense), class_name(sense), weight, class_size(sense), 0});
    // A word for a class that holds almost no kinds of its own names its
    // parent's things ("clothes" is WordNet's apparel, beside the clothing
    // that garments are; "dinnerware" beside tableware): the parent, one
    // step up. Only a collective word does ("clothes", "dinnerware"), not
    // the plural of a count noun with few kinds: "pots" are no containers.
    if (class_size(sense) > kCollectiveSize || wordnet == nullptr) continue;
    if (std::find(as_said.begin(), as_said.end(), sense) == as_said.end()) continue;
    if (auto s = wordnet->synset(sense))
      for (language::SynsetOffset parent : s->hypernyms)
        out.push_back(ConceptClass{concept_id(parent), class_name(parent), weight, class_size(parent), 1});
  }
  // A class word's other senses too, less weighed: a thing whose only
  // sense is not a physical one is still of the class said ("books" are
  // bound pages to WordNet first, a textbook a published work; "a textbook
  // is a book" all the same). A thing with a physical sense is profiled by
  // that one, so these match only such things.
  if (wordnet != nullptr) {
    std::vector<language::SynsetOffset> other = wordnet->noun_senses(phrase);
    add_base_form_senses(*wordnet, phrase, other);
    for (language::SynsetOffset o : other)
      if (std::none_of(out.begin(), out.end(), [&](const ConceptClass& c) { return c.id == concept_id(o); }))
        out.push_back(ConceptClass{concept_id(o), class_name(o), kOtherSenseWeight, class_size(o), 0});
  }
  return out;
}

std::vector<float> LexicalConcepts::vector_of(std::string_view words) const {
  std::vector<std::string> said = name_words(words, [this](std::string_view w) { return known_word(w); });
  return words_vector(said, std::vector<double>(said.size(), 1.0));
}

}  // namespace apprentice
