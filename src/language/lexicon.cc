#include "language/lexicon.h"

#include <algorithm>
#include <cctype>
#include <set>

#include <spdlog/spdlog.h>

#include "util/text.h"

namespace apprentice::language {
namespace {

// How far up the hypernym tree "is an ancestor of" and "is a container"
// look. WordNet's noun hierarchy is at most 20 deep; artifacts reach
// "container" within a few steps (garbage -> receptacle -> container).
constexpr int kMaxAncestorDepth = 12;
// How far below a class word a kind may be to be one of that class ("tool"
// is two steps above "hammer").
constexpr int kMaxClassDepth = 3;
constexpr int kMaxContainerDepth = 4;
// A word with more kinds than this directly below it in WordNet is too
// general to name one particular place: "receptacle" has 24 ("garbage" is
// one), "refrigerator" has 2 (one is "fridge").
constexpr std::size_t kMaxKindsOfASpecificWord = 3;
// A place word one step above the place's own name names it when it has
// at most this many kinds: "shelf" (4: bookshelf, hob, mantel, overmantel)
// does; "container" and "receptacle" (dozens) never name one place.
constexpr std::size_t kMaxKindsOfAPlaceWord = 6;

std::string spaced(std::string_view phrase) {
  std::string out = to_lower(phrase);
  for (char& c : out)
    if (c == '-' || c == '_') c = ' ';
  return join(split_words(out), " ");
}

std::string describe(const Synset& s) {
  std::vector<std::string> shown(s.lemmas.begin(), s.lemmas.begin() + std::min<std::size_t>(s.lemmas.size(), 4));
  return "{" + join(shown, ", ") + (s.lemmas.size() > 4 ? ", ...}" : "}");
}

bool is_material(const Synset& s) {
  return s.lexicographer_file == kLexSubstance || s.lexicographer_file == kLexFood;
}

bool contains(const std::vector<SynsetOffset>& v, SynsetOffset x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

// Whether a definition uses the phrase as words, allowing a plural on its
// last word: "... a cupboard with doors and shelves and drawers".
bool mentions(std::string_view gloss, std::string_view phrase) {
  std::vector<std::string> words;
  std::string current;
  for (char c : to_lower(gloss)) {
    if (std::isalpha(static_cast<unsigned char>(c))) {
      current.push_back(c);
    } else if (!current.empty()) {
      words.push_back(std::move(current));
      current.clear();
    }
  }
  if (!current.empty()) words.push_back(current);
  std::vector<std::string> target = split_words(phrase);
  if (target.empty() || words.size() < target.size()) return false;
  for (std::size_t i = 0; i + target.size() <= words.size(); ++i) {
    bool match = true;
    for (std::size_t j = 0; j < target.size() && match; ++j) {
      const std::string& w = words[i + j];
      const std::string& t = target[j];
      bool last = j + 1 == target.size();
      match = w == t || (last && (w == t + "s" || w == t + "es"));
    }
    if (match) return true;
  }
  return false;
}

// Candidate gerunds of a verb: "recycle" -> "recycling", "ship" ->
// "shipping"/"shiping"; WordNet decides which, if any, is a word.
std::vector<std::string> gerunds(const std::string& verb) {
  std::vector<std::string> out;
  if (verb.size() < 2) return out;
  if (verb.ends_with("ie")) out.push_back(verb.substr(0, verb.size() - 2) + "ying");
  if (verb.back() == 'e' && !verb.ends_with("ee")) out.push_back(verb.substr(0, verb.size() - 1) + "ing");
  out.push_back(verb + "ing");
  out.push_back(verb + verb.back() + "ing");
  return out;
}

}  // namespace

Lexicon Lexicon::open_default() {
  auto wordnet = WordNet::open();
  if (!wordnet) {
    spdlog::warn("wordnet: {}; words the world does not use will stay unknown", wordnet.error().message);
    return Lexicon(std::nullopt);
  }
  return Lexicon(std::move(*wordnet));
}

std::vector<Synset> Lexicon::synsets(std::string_view phrase) const {
  std::vector<Synset> out;
  if (!wordnet_) return out;
  for (SynsetOffset offset : wordnet_->noun_senses(spaced(phrase)))
    if (auto s = wordnet_->synset(offset)) out.push_back(std::move(*s));
  return out;
}

std::vector<std::string> Lexicon::lemmas(std::string_view phrase) const {
  std::vector<std::string> out;
  if (!wordnet_) return out;
  std::string text = spaced(phrase);
  std::vector<std::string> words = split_words(text);
  if (words.empty()) return out;
  auto add = [&](const std::string& form) {
    if (form != text && std::find(out.begin(), out.end(), form) == out.end()) out.push_back(form);
  };
  for (const std::string& form : wordnet_->noun_base_forms(text)) add(form);
  std::string last = words.back();
  for (const std::string& base : wordnet_->noun_base_forms(last)) {
    words.back() = base;
    add(join(words, " "));
  }
  return out;
}

std::vector<PhraseVariant> Lexicon::variants(std::string_view phrase) const {
  std::vector<PhraseVariant> out;
  if (!wordnet_) return out;
  std::string text = spaced(phrase);
  auto add = [&](std::string form, std::string reason) {
    if (form == text) return;
    for (const PhraseVariant& v : out)
      if (v.phrase == form) return;
    out.push_back({std::move(form), std::move(reason)});
  };
  for (const std::string& form : lemmas(text))
    add(form, "WordNet's morphology gives the base form '" + form + "' of '" + text + "'");
  std::vector<std::string> words = split_words(text);
  // A closed compound WordNet lists open: "trashcan" -> "trash can" (only
  // for words it lacks: "dishwasher" is a noun as it stands).
  if (words.size() == 1 && text.size() >= 6 && !wordnet_->has_noun(text)) {
    for (std::size_t k = 3; k + 3 <= text.size(); ++k) {
      std::string open = text.substr(0, k) + " " + text.substr(k);
      std::vector<std::string> forms{open};
      for (const std::string& base : lemmas(open)) forms.push_back(base);
      for (const std::string& form : forms)
        if (wordnet_->has_noun(form)) add(form, "WordNet lists '" + text + "' as the noun '" + form + "'");
    }
  }
  // A verb used as a modifier where WordNet has its gerund: "recycle bin".
  if (words.size() >= 2 && !wordnet_->has_noun(text) && wordnet_->has_verb(words[0]) &&
      !wordnet_->has_noun(words[0])) {
    for (const std::string& gerund : gerunds(words[0])) {
      std::vector<std::string> changed = words;
      changed[0] = gerund;
      std::string form = join(changed, " ");
      if (wordnet_->has_noun(form))
        add(form, "'" + words[0] + "' is a verb; WordNet has the noun '" + form + "'");
    }
  }
  return out;
}

std::vector<std::string> Lexicon::synonyms(std::string_view phrase) const {
  std::vector<std::string> out;
  std::string text = spaced(phrase);
  for (const Synset& s : synsets(text))
    for (const std::string& lemma : s.lemmas)
      if (lemma != text && std::find(out.begin(), out.end(), lemma) == out.end()) out.push_back(lemma);
  return out;
}

bool Lexicon::knows(std::string_view word) const { return wordnet_ && wordnet_->knows(spaced(word)); }

std::vector<std::string> Lexicon::verb_lemmas(std::string_view word) const {
  if (!wordnet_) return {};
  return wordnet_->verb_base_forms(spaced(word));
}

std::vector<std::string> Lexicon::adjective_lemmas(std::string_view word) const {
  if (!wordnet_) return {};
  return wordnet_->adjective_base_forms(spaced(word));
}

bool Lexicon::has_verb(std::string_view word) const { return wordnet_ && wordnet_->has_verb(spaced(word)); }

bool Lexicon::has_noun(std::string_view word) const { return wordnet_ && wordnet_->has_noun(spaced(word)); }

bool Lexicon::ancestor_of(SynsetOffset ancestor, const Synset& synset, std::string* path, int max_depth) const {
  std::vector<std::pair<SynsetOffset, std::string>> frontier{{synset.offset, describe(synset)}};
  std::set<SynsetOffset> seen{synset.offset};
  if (max_depth < 0) max_depth = kMaxAncestorDepth;
  for (int depth = 0; depth < max_depth && !frontier.empty(); ++depth) {
    std::vector<std::pair<SynsetOffset, std::string>> next;
    for (const auto& [offset, trail] : frontier) {
      auto s = wordnet_->synset(offset);
      if (!s) continue;
      for (SynsetOffset up : s->hypernyms) {
        if (!seen.insert(up).second) continue;
        auto u = wordnet_->synset(up);
        std::string extended = trail + " < " + (u ? describe(*u) : std::to_string(up));
        if (up == ancestor) {
          if (path) *path = extended;
          return true;
        }
        next.emplace_back(up, std::move(extended));
      }
    }
    frontier = std::move(next);
  }
  return false;
}

bool Lexicon::is_container(const Synset& synset) const {
  if (synset.lexicographer_file != kLexArtifact) return false;
  std::vector<SynsetOffset> frontier{synset.offset};
  for (int depth = 0; depth <= kMaxContainerDepth && !frontier.empty(); ++depth) {
    std::vector<SynsetOffset> next;
    for (SynsetOffset offset : frontier) {
      auto s = wordnet_->synset(offset);
      if (!s) continue;
      if (std::find(s->lemmas.begin(), s->lemmas.end(), "container") != s->lemmas.end()) return true;
      next.insert(next.end(), s->hypernyms.begin(), s->hypernyms.end());
    }
    frontier = std::move(next);
  }
  return false;
}

// What a place is for, when WordNet says so: the material senses of the
// phrase itself ("the trash" as a place; "garbage", which WordNet lists as
// both food waste and a receptacle — with `require_container` only such a
// phrase), and the modifier's of each "<material> <container>" lemma of its
// container senses ("garbage can", "waste basket"). A phrase WordNet lacks
// but whose head is a container ("rubbish bin") is for what its modifier
// names.
std::vector<Synset> Lexicon::contents(std::string_view phrase, const std::vector<Synset>& senses,
                                      bool require_container) const {
  std::vector<Synset> out;
  auto add_materials = [&](std::string_view word) {
    for (Synset& s : synsets(word))
      if (is_material(s)) out.push_back(std::move(s));
  };
  auto head_is_container = [&](const std::vector<std::string>& words) {
    for (const Synset& h : synsets(words.back()))
      if (is_container(h)) return true;
    return false;
  };
  bool container = false;
  for (const Synset& s : senses) {
    if (!is_container(s)) continue;
    container = true;
    for (const std::string& lemma : s.lemmas) {
      std::vector<std::string> words = split_words(lemma);
      if (words.size() < 2 || !head_is_container(words)) continue;
      words.pop_back();
      add_materials(join(words, " "));
    }
  }
  std::vector<std::string> words = split_words(phrase);
  if (container || !require_container) add_materials(phrase);
  if (senses.empty() && words.size() >= 2 && head_is_container(words)) {
    words.pop_back();
    add_materials(join(words, " "));
  }
  return out;
}

// Why WordNet relates two sets of senses, or "" if it does not: a shared
// synset, the phrase above the category (any depth, if the phrase is
// specific), the category directly above the phrase, or two artifacts each
// defined by the other.
std::string Lexicon::sense_relation(const std::string& text, const std::string& name, const std::vector<Synset>& mine,
                                    const std::vector<Synset>& theirs, bool as_container) const {
  for (const Synset& a : mine) {
    for (const Synset& c : theirs) {
      std::string path;
      bool same_file = a.lexicographer_file == c.lexicographer_file;
      if (a.offset == c.offset) return "'" + text + "' and '" + name + "' share the WordNet synset " + describe(a);
      if (same_file && a.hyponyms.size() <= kMaxKindsOfASpecificWord && ancestor_of(a.offset, c, &path))
        return "in WordNet a " + name + " is a kind of " + text + ": " + path;
      if (same_file && contains(a.hypernyms, c.offset))
        return "in WordNet " + describe(a) + " is a kind of " + describe(c);
      // "the shelf" for the bookshelf: a place named by the category's own
      // hypernym, one step up, a word of few kinds. (Not a thing: "toys" is
      // a class of things, read as one.)
      if (as_container && same_file && a.hyponyms.size() <= kMaxKindsOfAPlaceWord && contains(c.hypernyms, a.offset))
        return "in WordNet a " + name + " is a kind of " + text + ", one step up";
      if (a.lexicographer_file == kLexArtifact && same_file && mentions(c.gloss, text) && mentions(a.gloss, name))
        return "WordNet defines each by the other: " + name + " is '" + c.gloss + "', " + text + " is '" + a.gloss +
               "'";
    }
  }
  return "";
}

namespace {

// Why two places hold related materials, or "": the same material first,
// then one directly above the other, then sisters under one hypernym.
std::string content_relation(const std::string& text, const std::string& name, const std::vector<Synset>& mine,
                             const std::vector<Synset>& theirs) {
  enum Closeness { kSame, kAdjacent, kSisters };
  auto closeness = [](const Synset& m, const Synset& t) -> std::optional<Closeness> {
    if (m.offset == t.offset) return kSame;
    if (contains(m.hypernyms, t.offset) || contains(t.hypernyms, m.offset)) return kAdjacent;
    for (SynsetOffset h : m.hypernyms)
      if (contains(t.hypernyms, h)) return kSisters;
    return std::nullopt;
  };
  for (Closeness wanted : {kSame, kAdjacent, kSisters}) {
    for (const Synset& m : mine) {
      for (const Synset& t : theirs) {
        if (closeness(m, t) != wanted) continue;
        return "'" + text + "' is a place for " + describe(m) + " and in WordNet the " + name + " is a place for " +
               describe(t) +
               (wanted == kSame ? "" : wanted == kAdjacent ? ", a closely related material" : ", a sister material");
      }
    }
  }
  return "";
}

}  // namespace

std::vector<CategoryRelation> Lexicon::related(std::string_view phrase, std::span<const std::string> categories,
                                               bool as_container) const {
  std::vector<CategoryRelation> out;
  if (!wordnet_) return out;
  std::string text = spaced(phrase);
  std::vector<Synset> mine = synsets(text);
  std::vector<Synset> my_contents = as_container ? contents(text, mine, false) : std::vector<Synset>{};
  // Only senses that can be the thing meant take part: a place is an
  // artifact; an item may also be food or a substance. ("trash" as talk is
  // a kind of "garbage" as talk, which says nothing about receptacles.)
  auto physical = [&](std::vector<Synset> senses) {
    std::erase_if(senses, [&](const Synset& s) {
      return !(s.lexicographer_file == kLexArtifact || (!as_container && is_material(s)));
    });
    return senses;
  };
  std::vector<Synset> mine_physical = physical(mine);
  for (const std::string& category : categories) {
    std::string name = spaced(category);
    std::vector<Synset> theirs = synsets(name);
    std::string reason = sense_relation(text, name, mine_physical, physical(theirs), as_container);
    if (reason.empty() && as_container && !my_contents.empty())
      reason = content_relation(text, name, my_contents, contents(name, theirs, true));
    if (!reason.empty()) out.push_back({category, reason});
  }
  return out;
}

std::vector<std::string> Lexicon::kinds_under(std::string_view phrase, std::span<const std::string> categories) const {
  std::vector<std::string> out;
  if (!wordnet_) return out;
  auto physical = [](std::vector<Synset> senses) {
    std::erase_if(senses, [](const Synset& s) { return !(s.lexicographer_file == kLexArtifact || is_material(s)); });
    return senses;
  };
  std::vector<Synset> classes = physical(synsets(spaced(phrase)));
  for (const std::string& lemma : lemmas(phrase))  // "tools" -> "tool"
    for (Synset& s : physical(synsets(lemma))) classes.push_back(std::move(s));
  if (classes.empty()) return out;
  for (const std::string& category : categories) {
    std::vector<Synset> kinds = physical(synsets(spaced(category)));
    for (const std::string& lemma : lemmas(category))  // "saltines" -> "saltine"
      for (Synset& s : physical(synsets(lemma))) kinds.push_back(std::move(s));
    bool under = std::any_of(kinds.begin(), kinds.end(), [&](const Synset& kind) {
      return std::any_of(classes.begin(), classes.end(), [&](const Synset& c) {
        return c.offset != kind.offset && ancestor_of(c.offset, kind, nullptr, kMaxClassDepth);
      });
    });
    if (under) out.push_back(category);
  }
  return out;
}

}  // namespace apprentice::language
