#include "language/utterance.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <set>
#include <utility>

#include "language/parser.h"
#include "util/text.h"

namespace apprentice::language {
namespace {


bool is_letter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_alnum(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; }

// Curly quotes as ASCII; every other non-ASCII byte as a space.
std::string ascii(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    auto c = static_cast<unsigned char>(text[i]);
    if (c == 0xE2 && i + 2 < text.size() && static_cast<unsigned char>(text[i + 1]) == 0x80) {
      auto third = static_cast<unsigned char>(text[i + 2]);
      if (third == 0x98 || third == 0x99) out.push_back('\'');
      else if (third == 0x9C || third == 0x9D) out.push_back('"');
      else out.push_back(' ');
      i += 2;
      continue;
    }
    out.push_back(c < 0x80 ? static_cast<char>(std::tolower(c)) : ' ');
  }
  return out;
}

// Raw words and clause breaks: letters, digits and inner apostrophes and
// hyphens make words; , ; : . ! ? ( ) and a free-standing dash break clauses.
std::vector<std::string> raw_words(const std::string& text) {
  std::vector<std::string> words;
  std::string current;
  auto flush = [&] {
    if (!current.empty()) words.push_back(std::move(current));
    current.clear();
  };
  auto brk = [&] {
    flush();
    if (!words.empty() && words.back() != ",") words.emplace_back(",");
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    char prev = i > 0 ? text[i - 1] : ' ';
    char next = i + 1 < text.size() ? text[i + 1] : ' ';
    if (is_alnum(c)) {
      current.push_back(c);
    } else if (c == '\'' && is_letter(prev) && !current.empty()) {
      current.push_back(c);  // "that's", and "cans'" (dropped below)
    } else if (c == '-' && is_alnum(prev) && is_alnum(next) && !current.empty()) {
      current.push_back(c);
    } else if (is_one_of(std::string_view(&c, 1), {",", ";", ":", ".", "!", "?", "(", ")", "-"})) {
      brk();
    } else if (c == '&' || c == '+') {
      flush();
      words.emplace_back("and");
    } else {
      flush();
    }
  }
  flush();
  while (!words.empty() && words.back() == ",") words.pop_back();
  return words;
}

// What follows "X's" when it means "X is".
bool starts_a_predicate(std::string_view next) {
  return is_one_of(next, {"in", "into", "inside", "on", "onto", "going", "gone", "supposed", "meant", "done",
                          "finished", "kept", "closed", "shut", "open", "not", "a", "an", "the", "trash", "garbage",
                          "rubbish", "where", "always", "usually", "to", "back", "put", "stored", "fine", "right",
                          "wrong", "correct", "all", "just", "also", "it", "that", "everything", "recycling",
                          "for", "over", "empty", "clear", "clean", "next", "okay", "ok", "good", "enough"});
}

// Shorthand and contractions written out, as whole words.
const std::array<std::pair<std::string_view, std::string_view>, 28> kShorthand{{
    {"can't", "can not"},     {"cannot", "can not"},   {"won't", "will not"},   {"ain't", "is not"},
    {"let's", "let us"},      {"gonna", "going to"},   {"wanna", "want to"},    {"gotta", "got to"},
    {"lemme", "let me"},      {"pls", "please"},       {"plz", "please"},       {"thx", "thanks"},
    {"okay", "ok"},           {"k", "ok"},             {"u", "you"},            {"ya", "you"},
    {"dont", "do not"},       {"doesnt", "does not"},  {"isnt", "is not"},      {"thats", "that is"},
    {"whats", "what is"},     {"lets", "let us"},      {"w", "with"},           {"w/", "with"},
    {"rn", "right now"},      {"cuz", "because"},      {"bc", "because"},       {"tmrw", "tomorrow"},
}};

// A word said long for feeling ("noo", "yesss", "okkk", "sooo"): the word.
std::string_view without_drawl(std::string_view word) {
  auto only = [&](std::string_view head, char last) {
    if (word.size() <= head.size() + 1 || !word.starts_with(head)) return false;
    return std::all_of(word.begin() + static_cast<long>(head.size()), word.end(), [&](char c) { return c == last; });
  };
  if (only("n", 'o')) return "no";
  if (only("ye", 's')) return "yes";
  if (only("yea", 'h')) return "yeah";
  if (only("o", 'k')) return "ok";
  if (only("nop", 'e')) return "nope";
  return word;
}

void expand(const std::string& word, const std::string& next, std::vector<std::string>& out) {
  if (std::string_view plain = without_drawl(word); plain != word) {
    out.emplace_back(plain);
    return;
  }
  // "ill take it down later", "ill do it": I'll, before a verb of doing.
  if (word == "ill" && is_one_of(next, {"take", "do", "put", "get", "deal", "sort", "move", "handle", "grab", "bring",
                                        "be", "finish", "clean", "wash", "use", "wear", "leave", "need", "keep", "fix"})) {
    out.emplace_back("i");
    out.emplace_back("will");
    return;
  }
  // "ya", first in a reply, is a yes ("ya", "ya sure"); "see ya", "ya
  // know" are you.
  if (word == "ya" && out.empty() && next != "know") {
    out.emplace_back("yeah");
    return;
  }
  for (const auto& [from, to] : kShorthand) {
    if (word == from) {
      for (std::string& w : split_words(to)) out.push_back(std::move(w));
      return;
    }
  }
  auto apostrophe = word.find('\'');
  if (apostrophe == std::string::npos) {
    out.push_back(word);
    return;
  }
  std::string stem = word.substr(0, apostrophe);
  std::string tail = word.substr(apostrophe);
  if (tail == "'t" && stem.ends_with("n")) {  // don't, isn't, shouldn't
    stem.pop_back();
    out.push_back(stem);
    out.emplace_back("not");
  } else if (tail == "'re") {
    out.push_back(stem);
    out.emplace_back("are");
  } else if (tail == "'ll") {
    out.push_back(stem);
    out.emplace_back("will");
  } else if (tail == "'d") {
    out.push_back(stem);
    out.emplace_back("would");
  } else if (tail == "'m") {
    out.push_back(stem);
    out.emplace_back("am");
  } else if (tail == "'ve") {
    out.push_back(stem);
    out.emplace_back("have");
  } else if (tail == "'s") {
    out.push_back(stem);
    bool pronoun = is_one_of(stem, {"it", "that", "what", "there", "here", "he", "she", "who", "where", "this",
                                    "everything", "nothing", "which", "how"});
    if (pronoun || starts_a_predicate(next)) out.emplace_back("is");
    // Otherwise a possessive: "the fridge's door" is "the fridge door".
  } else {
    out.push_back(stem);  // "cans'" and stray apostrophes
  }
}

}  // namespace

void expand_shorthand(std::vector<std::string>& words) {
  std::vector<std::string> out;
  out.reserve(words.size());
  for (std::size_t i = 0; i < words.size(); ++i) {
    std::string& word = words[i];
    word = std::string(without_drawl(word));
    // "ya", first, is a yes, as reply_words reads it.
    if (word == "ya" && out.empty() && (i + 1 == words.size() || words[i + 1] != "know")) {
      out.emplace_back("yeah");
      continue;
    }
    const auto* written = std::find_if(kShorthand.begin(), kShorthand.end(), [&](const auto& entry) { return entry.first == word; });
    if (written == kShorthand.end()) {
      out.push_back(std::move(word));
    } else {
      for (std::string& w : split_words(written->second)) out.push_back(std::move(w));
    }
  }
  words = std::move(out);
}

std::vector<std::string> reply_words(std::string_view text) {
  std::vector<std::string> raw = raw_words(ascii(text.substr(0, std::min(text.size(), kMaxSentenceBytes))));
  std::vector<std::string> out;
  for (std::size_t i = 0; i < raw.size() && out.size() < kMaxSentenceWords; ++i)
    expand(raw[i], i + 1 < raw.size() ? raw[i + 1] : "", out);
  if (out.size() > kMaxSentenceWords) out.resize(kMaxSentenceWords);
  // "the top of the piano", "the edge of the tub": a part of a thing named
  // as places are named here, "the piano top", "the tub edge".
  for (std::size_t i = 0; i + 2 < out.size(); ++i) {
    if (!is_one_of(out[i], {"top", "side", "edge", "inside", "surface", "corner"}) || out[i + 1] != "of") continue;
    const std::size_t noun = i + 2 + (is_one_of(out[i + 2], {"the", "a", "my", "that", "this"}) ? 1 : 0);
    if (noun >= out.size() || !std::isalpha(static_cast<unsigned char>(out[noun].front()))) continue;
    std::string part = out[i];
    out[i] = out[noun];
    out[i + 1] = part;
    out.erase(out.begin() + static_cast<std::ptrdiff_t>(i + 2), out.begin() + static_cast<std::ptrdiff_t>(noun + 1));
  }
  return out;
}

std::string quoted_words(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) {
    if (!out.empty() && w != ",") out += ' ';
    out += w;
  }
  return out;
}

std::vector<std::string> name_parts(std::string_view name) {
  std::vector<std::string> parts;
  std::string part;
  for (char c : name) {
    if (c == '-' || c == ' ' || c == '_') {
      if (!part.empty()) parts.push_back(std::move(part));
      part.clear();
    } else {
      part.push_back(c);
    }
  }
  if (!part.empty()) parts.push_back(std::move(part));
  return parts;
}

void split_hyphenated_kinds(std::vector<std::string>& words, const Universe& universe) {
  for (std::size_t i = 0; i < words.size(); ++i)
    if (words[i].find('-') != std::string::npos && !universe.with_category(words[i]).empty()) {
      std::vector<std::string> parts = name_parts(words[i]);
      words.erase(words.begin() + static_cast<std::ptrdiff_t>(i));
      words.insert(words.begin() + static_cast<std::ptrdiff_t>(i), parts.begin(), parts.end());
      i += parts.size() - 1;
    }
}

void join_world_names(std::vector<std::string>& words, const Universe& universe) {
  // The names worth joining, longest first so that the longest match wins.
  std::vector<std::pair<std::string, std::vector<std::string>>> names;
  for (const ObjectInfo& info : universe.objects()) {
    std::vector<std::string> parts = name_parts(info.category);
    bool function_word = std::any_of(parts.begin(), parts.end(), [](const std::string& p) {
      return is_one_of(p, {"in", "on", "and", "of", "the", "a", "an", "to", "with", "at", "from", "into", "is",
                           "for", "by", "off", "out", "up"});
    });
    if (parts.size() < 2 || !function_word) continue;
    if (std::none_of(names.begin(), names.end(), [&](const auto& n) { return n.first == info.category; }))
      names.emplace_back(info.category, std::move(parts));
  }
  if (names.empty()) {
    join_split_names(words, universe);
    separate_listed_names(words, universe);
    return;
  }
  std::sort(names.begin(), names.end(), [](const auto& a, const auto& b) { return a.second.size() > b.second.size(); });
  // Each word split on hyphens, remembering which word each part came from.
  std::vector<std::string> parts;
  std::vector<std::size_t> owner;
  for (std::size_t i = 0; i < words.size(); ++i)
    for (std::string& p : name_parts(words[i])) {
      parts.push_back(std::move(p));
      owner.push_back(i);
    }
  std::vector<std::string> out;
  std::size_t next_word = 0;
  for (std::size_t at = 0; at < parts.size();) {
    bool joined = false;
    // Only at a word's first part, so that a match never splits a word.
    if (owner[at] >= next_word && (at == 0 || owner[at - 1] != owner[at])) {
      for (const auto& [category, name] : names) {
        if (at + name.size() > parts.size()) continue;
        bool match = true;
        for (std::size_t k = 0; k < name.size() && match; ++k) {
          const std::string& p = parts[at + k];
          bool last = k + 1 == name.size();
          match = p == name[k] || (last && (p == name[k] + "s" || p == name[k] + "es"));
        }
        std::size_t end = at + name.size();
        // ... and never ends inside one.
        if (!match || (end < parts.size() && owner[end] == owner[end - 1])) continue;
        for (std::size_t w = next_word; w < owner[at]; ++w) out.push_back(words[w]);
        out.push_back(category);
        next_word = owner[end - 1] + 1;
        at = end;
        joined = true;
        break;
      }
    }
    if (!joined) ++at;
  }
  for (std::size_t w = next_word; w < words.size(); ++w) out.push_back(words[w]);
  words = std::move(out);
  join_split_names(words, universe);
  separate_listed_names(words, universe);
}

std::vector<std::string> properties_said(const Universe& universe, ObjectId thing, std::string_view text) {
  const std::vector<std::string> words = split_words(to_lower(text));
  std::vector<std::string> said;
  for (const std::string& property : universe.info(thing).properties)
    if (std::find(words.begin(), words.end(), property) != words.end()) said.push_back(property);
  return said;
}

void separate_listed_names(std::vector<std::string>& words, const Universe& universe) {
  std::set<std::string> one_word;  // the one-word kinds of things here: "rake", "hoe"
  std::set<std::string> two_words;  // "paper plate", for its words said together
  for (const ObjectInfo& info : universe.objects()) {
    if (info.kind != ObjectKind::kItem) continue;
    const std::vector<std::string> parts = name_parts(info.category);
    if (parts.size() == 1) one_word.insert(parts.front());
    if (parts.size() == 2) two_words.insert(parts[0] + " " + parts[1]);
  }
  if (one_word.size() < 3) return;
  auto names_a_kind = [&](const std::string& word) {
    const std::vector<std::string> forms = singular_forms(word);
    return std::any_of(forms.begin(), forms.end(), [&](const std::string& f) { return one_word.count(f) > 0; });
  };
  auto one_name = [&](const std::string& a, const std::string& b) {
    const std::vector<std::string> forms = singular_forms(b);
    return std::any_of(forms.begin(), forms.end(), [&](const std::string& f) { return two_words.count(a + " " + f) > 0; });
  };
  std::vector<std::string> out;
  for (std::size_t i = 0; i < words.size();) {
    std::size_t end = i;
    while (end < words.size() && names_a_kind(words[end]) && (end == i || !one_name(words[end - 1], words[end]))) ++end;
    // ("rake shovel and hoe": two, then the last after "and".)
    const bool and_one_more = end - i == 2 && end + 1 < words.size() && is_one_of(words[end], {"and", "&", "n"}) &&
                              names_a_kind(words[end + 1]);
    if (end - i >= 3 || and_one_more) {
      for (std::size_t k = i; k < end; ++k) {
        if (k > i) out.push_back(",");
        out.push_back(words[k]);
      }
      i = end;
    } else {
      out.push_back(words[i]);
      ++i;
    }
  }
  words = std::move(out);
}

void join_split_names(std::vector<std::string>& words, const Universe& universe) {
  std::set<std::string> closed;  // one-word parts of names: "toolbox", "workbench"
  for (const ObjectInfo& info : universe.objects())
    for (std::string& part : name_parts(info.category))
      if (part.size() >= 6) closed.insert(std::move(part));
  std::vector<std::string> out;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i + 1 < words.size() && words[i].size() >= 2 && words[i + 1].size() >= 2) {
      const std::string together = words[i] + words[i + 1];
      const bool plural = together.size() > 1 && together.back() == 's' && closed.count(together.substr(0, together.size() - 1));
      if (closed.count(together) || plural) {
        out.push_back(together);
        ++i;
        continue;
      }
    }
    out.push_back(words[i]);
  }
  words = std::move(out);
}

bool erase_phrase(std::vector<std::string>& words, const std::vector<std::string_view>& phrase) {
  bool erased = false;
  if (phrase.empty()) return false;
  for (std::size_t i = 0; i + phrase.size() <= words.size();) {
    if (std::equal(phrase.begin(), phrase.end(), words.begin() + static_cast<std::ptrdiff_t>(i))) {
      words.erase(words.begin() + static_cast<std::ptrdiff_t>(i),
                  words.begin() + static_cast<std::ptrdiff_t>(i + phrase.size()));
      erased = true;
    } else {
      ++i;
    }
  }
  return erased;
}

bool is_determiner(std::string_view w) {
  return is_one_of(w, {"the", "a", "an", "this", "that", "these", "those", "my", "your", "our", "his", "her", "its",
                       "their", "some", "any", "all", "every", "each", "both", "another"});
}

bool is_object_pronoun(std::string_view w) {
  return is_one_of(w, {"it", "this", "that", "them", "they", "these", "those", "itself"});
}

bool is_copula(std::string_view w) { return is_one_of(w, {"is", "are", "be", "was", "were", "am", "been", "being"}); }

bool is_auxiliary(std::string_view w) {
  return is_one_of(w, {"should", "must", "will", "would", "can", "could", "may", "might", "shall", "need", "needs",
                       "has", "have", "had", "do", "does", "did", "ought", "to", "supposed", "meant", "going",
                       "got", "gets", "get", "always", "usually", "normally", "also", "probably", "definitely"});
}

bool is_negation(std::string_view w) { return is_one_of(w, {"not", "never"}); }

bool is_generic_noun(std::string_view w) {
  return is_one_of(w, {"thing", "things", "stuff", "everything", "anything", "something", "object", "objects",
                       "item", "items", "whatever", "what", "rest", "all", "one", "ones", "others", "remaining", "other",
                       "same", "else"});
}

bool is_door_word(std::string_view w) { return is_one_of(w, {"door", "doors", "lid", "lids", "cover", "hatch"}); }

bool is_verb_of_going(std::string_view w) { return is_one_of(w, {"go", "goes", "belong", "belongs", "live", "lives"}); }

bool is_particle(std::string_view w) {
  return is_one_of(w, {"away", "up", "down", "back", "out", "off", "over", "aside"});
}

bool is_state_word(std::string_view w) { return is_one_of(w, {"closed", "shut", "open", "opened", "shutted"}); }

bool is_filler(std::string_view w) {
  return is_one_of(w, {"please", "ok", "just", "now", "um", "uh", "er", "erm", "hmm", "hm", "so", "well", "oh",
                       "hey", "alright", "actually", "basically", "simply", "kindly", "thanks", "first", "next",
                       "afterwards", "afterward", "later", "finally", "lastly", "again", "too", "quickly",
                       "carefully", "today", "instead", "anyway"});
}

bool is_clause_break(std::string_view w) {
  return is_one_of(w, {",", "and", "then", "but", "plus", "also", "afterwards", "after", "before", "once", "when",
                       "because", "since", "or", "so", "with", "while", "until"});
}

std::optional<std::size_t> ordinal(std::string_view w) {
  static const std::array<std::pair<std::string_view, std::size_t>, 16> kOrdinals{{
      {"first", 0}, {"1st", 0}, {"1", 0},  {"second", 1}, {"2nd", 1}, {"2", 1},  {"third", 2}, {"3rd", 2},
      {"3", 2},     {"fourth", 3}, {"4th", 3}, {"4", 3}, {"fifth", 4}, {"5th", 4}, {"5", 4},     {"one", 0},
  }};
  for (const auto& [word, index] : kOrdinals)
    if (w == word) return index;
  return std::nullopt;
}

std::string irregular_verb_base(std::string_view word) {
  static const std::array<std::pair<std::string_view, std::string_view>, 34> kIrregular{{
      {"went", "go"},     {"gone", "go"},      {"goes", "go"},       {"kept", "keep"},   {"left", "leave"},
      {"threw", "throw"}, {"thrown", "throw"}, {"took", "take"},     {"taken", "take"},  {"brought", "bring"},
      {"got", "get"},     {"gotten", "get"},   {"held", "hold"},     {"stuck", "stick"}, {"sat", "sit"},
      {"put", "put"},     {"set", "set"},      {"shut", "shut"},     {"did", "do"},      {"done", "do"},
      {"does", "do"},     {"made", "make"},    {"hung", "hang"},     {"lay", "lay"},     {"laid", "lay"},
      {"found", "find"},  {"stood", "stand"},  {"swept", "sweep"},   {"dealt", "deal"},  {"ran", "run"},
      {"emptied", "empty"}, {"tidied", "tidy"}, {"carried", "carry"}, {"dried", "dry"},
  }};
  for (const auto& [form, base] : kIrregular)
    if (word == form) return std::string(base);
  return "";
}

std::vector<std::string> regular_verb_bases(std::string_view word) {
  std::vector<std::string> out;
  std::string w(word);
  auto add = [&](std::string s) {
    if (s.size() >= 2 && std::find(out.begin(), out.end(), s) == out.end()) out.push_back(std::move(s));
  };
  auto undouble = [&](const std::string& stem) {
    if (stem.size() >= 3 && stem[stem.size() - 1] == stem[stem.size() - 2]) add(stem.substr(0, stem.size() - 1));
  };
  if (w.ends_with("ies")) add(w.substr(0, w.size() - 3) + "y");
  if (w.ends_with("ied")) add(w.substr(0, w.size() - 3) + "y");
  if (w.ends_with("ing")) {
    std::string stem = w.substr(0, w.size() - 3);
    add(stem);
    add(stem + "e");
    undouble(stem);
  }
  if (w.ends_with("ed")) {
    std::string stem = w.substr(0, w.size() - 2);
    add(stem);
    add(stem + "e");
    undouble(stem);
  }
  if (w.ends_with("es")) add(w.substr(0, w.size() - 2));
  if (w.ends_with("s") && !w.ends_with("ss")) add(w.substr(0, w.size() - 1));
  return out;
}

}  // namespace apprentice::language
