#include "language/parser.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <span>
#include <string>

#include "util/text.h"

namespace apprentice::language {
namespace {

using WordSpan = std::span<const std::string>;


bool is_article(std::string_view w) { return is_one_of(w, {"the", "a", "an"}); }
bool is_grammar_copula(std::string_view w) { return w == "is" || w == "are"; }
bool is_in(std::string_view w) { return is_one_of(w, {"in", "into", "inside"}); }
bool is_on(std::string_view w) { return w == "on" || w == "onto"; }

// WordSpan that structure a sentence and so can never be part of a noun phrase.
bool is_structural(std::string_view w) {
  return is_article(w) || is_grammar_copula(w) || is_in(w) || is_on(w) ||
         is_one_of(w, {",", "if", "then", "that", "from"});
}

std::string phrase(WordSpan words) { return join(std::vector<std::string>(words.begin(), words.end()), " "); }

Error expected(std::string_view what, std::string_view where) {
  return Error{ErrorCode::kInvalidInput,
               "expected " + std::string(what) + (where.empty() ? "" : " " + std::string(where))};
}

// An optional article and then at least one word. `allow_and` admits "and"
// inside the phrase ("half and half"); place phrases after "in"/"on" refuse
// it, so that "in the fridge and closed" is not read as one odd place.
std::optional<NounPhrase> noun_phrase(WordSpan words, bool allow_and) {
  NounPhrase np;
  if (!words.empty() && is_article(words.front())) {
    np.article = words.front();
    words = words.subspan(1);
  }
  if (words.empty()) return std::nullopt;
  for (const std::string& w : words) {
    if (is_structural(w)) return std::nullopt;
    if (w == "and" && (!allow_and || &w == &words.front() || &w == &words.back())) return std::nullopt;
  }
  np.words.assign(words.begin(), words.end());
  return np;
}

Result<NounPhrase> require_noun_phrase(WordSpan words, bool allow_and, std::string_view where) {
  if (auto np = noun_phrase(words, allow_and)) return *np;
  if (words.empty()) return tl::unexpected(expected("a noun phrase", where));
  return tl::unexpected(expected("a noun phrase", std::string(where) + ", got " + quoted(phrase(words))));
}

bool starts_with(WordSpan words, std::initializer_list<std::string_view> prefix) {
  if (words.size() < prefix.size()) return false;
  return std::equal(prefix.begin(), prefix.end(), words.begin());
}

// "in the dish rack" / "on the table" after "an object is".
Result<std::pair<Relation, NounPhrase>> located(WordSpan words, std::string_view where) {
  if (words.empty() || (!is_in(words[0]) && !is_on(words[0])))
    return tl::unexpected(expected("'in' or 'on'", where));
  Relation relation = is_in(words[0]) ? Relation::kIn : Relation::kOn;
  auto place = require_noun_phrase(words.subspan(1), false, "after " + quoted(words[0]));
  if (!place) return tl::unexpected(place.error());
  return std::pair{relation, *place};
}

// "Repeat the following tasks while an object is on the table."
Result<LogicalForm> repeat_while(WordSpan w) {
  if (!starts_with(w, {"repeat", "the", "following"}) || w.size() < 5 ||
      (w[3] != "tasks" && w[3] != "task") || w[4] != "while")
    return tl::unexpected(expected("'repeat the following tasks while ...'", ""));
  WordSpan rest = w.subspan(5);
  if (rest.size() < 3 || (rest[0] != "an" && rest[0] != "a") || rest[1] != "object" || !is_grammar_copula(rest[2]))
    return tl::unexpected(expected("'an object is' after 'while'", ""));
  auto loc = located(rest.subspan(3), "after 'an object is'");
  if (!loc) return tl::unexpected(loc.error());
  return RepeatWhile{loc->first, loc->second};
}

// WordSpan that make a phrasal verb of the verb before them: "put away",
// "throw out", "clean up".
bool is_grammar_particle(std::string_view w) { return is_one_of(w, {"away", "back", "out", "up", "down", "off"}); }

// "Clear an object that is on the table.", "Put away an object that is on
// the desk." (a phrasal verb's particle stays part of the verb).
std::optional<Result<LogicalForm>> subtask_command(WordSpan w) {
  std::size_t verb_words = w.size() > 1 && is_grammar_particle(w[1]) ? 2 : 1;
  WordSpan rest = w.subspan(verb_words);
  if (rest.size() < 4 || (rest[0] != "an" && rest[0] != "a") || rest[1] != "object" || rest[2] != "that")
    return std::nullopt;
  if (!is_grammar_copula(rest[3])) return Result<LogicalForm>(tl::unexpected(expected("'is' after 'an object that'", "")));
  auto loc = located(rest.subspan(4), "after 'an object that is'");
  if (!loc) return Result<LogicalForm>(tl::unexpected(loc.error()));
  return Result<LogicalForm>(SubtaskCommand{phrase(w.first(verb_words)), loc->first, loc->second});
}

// The predicate after "is"/"are".
Result<Conjunct> predicate(const NounPhrase& subject, WordSpan p) {
  if (p.empty()) return tl::unexpected(expected("a predicate after 'is'", ""));
  if ((is_in(p[0]) || is_on(p[0])) && p.size() > 1) {
    if (auto place = noun_phrase(p.subspan(1), false))
      return Placement{subject, is_in(p[0]) ? Relation::kIn : Relation::kOn, *place};
  }
  PropertyStatement statement{subject, Property::kUnknown, {p.begin(), p.end()}};
  if (p.size() == 1 && (p[0] == "closed" || p[0] == "shut")) statement.property = Property::kClosed;
  if (p.size() == 1 && (p[0] == "open" || p[0] == "opened")) statement.property = Property::kOpen;
  return statement;
}

Result<Conjunct> relation(WordSpan segment) {
  auto copula = std::find_if(segment.begin(), segment.end(), [](const std::string& w) { return is_grammar_copula(w); });
  auto at = static_cast<std::size_t>(copula - segment.begin());
  if (at == 0) return tl::unexpected(expected("a noun phrase before 'is'", "in " + quoted(phrase(segment))));
  if (segment[0] == "there")
    return tl::unexpected(expected("a noun phrase before 'is'", "('there is ...' is not understood)"));
  auto subject = require_noun_phrase(segment.first(at), true, "before " + quoted(segment[at]));
  if (!subject) return tl::unexpected(subject.error());
  return predicate(*subject, segment.subspan(at + 1));
}

// Splits "A is P and B is Q, and C is R" into relations. A piece without a
// copula belongs to its neighbour: before the first relation it is part of
// a subject ("the half and half is ..."), after it part of a predicate
// ("the dishwasher is closed and started").
Result<std::vector<Conjunct>> conjunction(WordSpan w) {
  struct Piece { std::size_t begin, end; bool copula; };
  std::vector<Piece> pieces;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= w.size(); ++i) {
    if (i < w.size() && w[i] != "and" && w[i] != ",") continue;
    if (i > start) {
      bool copula = std::any_of(w.begin() + start, w.begin() + i, [](const std::string& x) { return is_grammar_copula(x); });
      pieces.push_back({start, i, copula});
    }
    start = i + 1;
  }
  if (pieces.empty()) return tl::unexpected(expected("a statement after 'the goal is that'", ""));
  std::vector<Piece> merged;
  std::optional<std::size_t> pending_begin;
  for (const Piece& piece : pieces) {
    if (piece.copula) {
      merged.push_back({pending_begin.value_or(piece.begin), piece.end, true});
      pending_begin.reset();
    } else if (merged.empty()) {
      if (!pending_begin) pending_begin = piece.begin;
    } else {
      merged.back().end = piece.end;
    }
  }
  if (merged.empty()) return tl::unexpected(expected("'is' or 'are'", "after 'the goal is that'"));
  if (pending_begin) return tl::unexpected(expected("'is' or 'are'", "at the end"));
  std::vector<Conjunct> conjuncts;
  for (const Piece& piece : merged) {
    auto c = relation(w.subspan(piece.begin, piece.end - piece.begin));
    if (!c) return tl::unexpected(c.error());
    conjuncts.push_back(std::move(*c));
  }
  return conjuncts;
}

Result<LogicalForm> goal_statement(WordSpan w, std::optional<NounPhrase> category) {
  if (!starts_with(w, {"the", "goal", "is"})) return tl::unexpected(expected("'the goal is that'", ""));
  if (w.size() < 4 || w[3] != "that") return tl::unexpected(expected("'that' after 'the goal is'", ""));
  auto conjuncts = conjunction(w.subspan(4));
  if (!conjuncts) return tl::unexpected(conjuncts.error());
  return GoalDescription{std::move(category), std::move(*conjuncts)};
}

// "If the object is a ketchup then the goal is that ..."
Result<LogicalForm> goal_description(WordSpan w) {
  if (!starts_with(w, {"if", "the", "object"}) || w.size() < 4 || !is_grammar_copula(w[3]))
    return tl::unexpected(expected("'if the object is'", ""));
  auto then = std::find(w.begin() + 4, w.end(), "then");
  if (then == w.end()) return tl::unexpected(expected("'then'", "after 'if the object is ...'"));
  auto at = static_cast<std::size_t>(then - w.begin());
  auto category = require_noun_phrase(w.subspan(4, at - 4), false, "after 'if the object is'");
  if (!category) return tl::unexpected(category.error());
  return goal_statement(w.subspan(at + 1), *category);
}

std::size_t find_word(WordSpan w, std::size_t from, bool (*pred)(std::string_view)) {
  for (std::size_t i = from; i < w.size(); ++i)
    if (pred(w[i])) return i;
  return w.size();
}

// "open X", "close X", "pick up X [from Y]", "put [down] X in|on Y"; the
// primitives' own names "pick-up" and "put-down" are read as those verbs.
Result<LogicalForm> action(WordSpan w) {
  ActionCommand command;
  if (w[0] == "open" || w[0] == "close") {
    command.verb = w[0] == "open" ? ActionVerb::kOpen : ActionVerb::kClose;
    auto object = require_noun_phrase(w.subspan(1), true, "after " + quoted(w[0]));
    if (!object) return tl::unexpected(object.error());
    command.object = *object;
    return command;
  }
  if (w[0] == "pick" || w[0] == "pick-up") {
    std::size_t start = w[0] == "pick-up" ? 1 : 2;
    std::size_t from = find_word(w, 1, [](std::string_view x) { return x == "from"; });
    // "pick X up [from Y]": the particle after the object.
    std::size_t object_end = from;
    if (w[0] == "pick" && (w.size() < 2 || w[1] != "up")) {
      if (from < 3 || w[from - 1] != "up") return tl::unexpected(expected("'up' after 'pick'", ""));
      start = 1;
      object_end = from - 1;
    }
    command.verb = ActionVerb::kPickUp;
    auto object = require_noun_phrase(w.subspan(start, object_end - start), true, "after 'pick up'");
    if (!object) return tl::unexpected(object.error());
    command.object = *object;
    if (from < w.size()) {
      auto source = require_noun_phrase(w.subspan(from + 1), false, "after 'from'");
      if (!source) return tl::unexpected(source.error());
      command.preposition = ActionPreposition::kFrom;
      command.destination = *source;
    }
    return command;
  }
  command.verb = ActionVerb::kPut;
  // "put down X", "put away X", "put X back in Y": particles say nothing
  // about where the thing goes.
  std::size_t start = w.size() > 1 && w[0] == "put" && is_grammar_particle(w[1]) ? 2 : 1;
  std::size_t prep = find_word(w, start, [](std::string_view x) { return is_in(x) || is_on(x); });
  if (prep == w.size()) return tl::unexpected(expected("'in' or 'on' and a place", "after 'put'"));
  std::size_t object_end = prep > start + 1 && is_grammar_particle(w[prep - 1]) ? prep - 1 : prep;
  auto object = require_noun_phrase(w.subspan(start, object_end - start), true, "after 'put'");
  if (!object) return tl::unexpected(object.error());
  auto place = require_noun_phrase(w.subspan(prep + 1), false, "after " + quoted(w[prep]));
  if (!place) return tl::unexpected(place.error());
  command.object = *object;
  command.preposition = is_in(w[prep]) ? ActionPreposition::kIn : ActionPreposition::kOn;
  command.destination = *place;
  return command;
}

bool is_plain_word(std::string_view w) {
  if (w.empty() || !std::isalpha(static_cast<unsigned char>(w.front()))) return false;
  return std::all_of(w.begin(), w.end(), [](char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '-';
  });
}

// An imperative with an unknown verb names a task: "Tidy kitchen."
std::optional<LogicalForm> task_name(WordSpan w) {
  if (!is_plain_word(w[0]) || is_structural(w[0]) ||
      is_one_of(w[0], {"and", "yes", "no", "you", "there", "what", "who", "where", "when", "why", "how",
                       "i", "it", "this", "goal", "object", "repeat"}))
    return std::nullopt;
  if (w.size() > 1 && !noun_phrase(w.subspan(1), false)) return std::nullopt;
  return TaskName{{w.begin(), w.end()}};
}

bool is_quote(char c) { return c == '"' || c == '\'' || c == '`'; }

}  // namespace

std::vector<std::string> tokenize(std::string_view sentence) {
  std::string_view text = trim(sentence);
  auto strip = [&] {
    bool changed = true;
    while (changed && !text.empty()) {
      changed = false;
      char last = text.back();
      if (last == '.' || last == '!' || last == '?' || is_quote(last) ||
          std::isspace(static_cast<unsigned char>(last))) {
        text.remove_suffix(1);
        changed = true;
      }
      if (!text.empty() && (is_quote(text.front()) || std::isspace(static_cast<unsigned char>(text.front())))) {
        text.remove_prefix(1);
        changed = true;
      }
    }
  };
  strip();
  std::vector<std::string> tokens;
  for (std::string& word : split_words(to_lower(text))) {
    std::size_t commas = 0;
    // A sentence's end inside a reply ("It's a mess. Tidy it.") breaks it
    // as a comma does.
    while (!word.empty() && (word.back() == ',' || word.back() == ';' || word.back() == '.' || word.back() == '!' ||
                             word.back() == '?')) {
      word.pop_back();
      ++commas;
    }
    if (!word.empty()) tokens.push_back(std::move(word));
    if (commas > 0) tokens.emplace_back(",");
  }
  return tokens;
}

Result<LogicalForm> parse(std::string_view sentence) {
  if (sentence.size() > kMaxSentenceBytes)
    return make_error(ErrorCode::kInvalidInput, "sentence longer than " + std::to_string(kMaxSentenceBytes) + " bytes");
  std::vector<std::string> tokens = tokenize(sentence);
  if (tokens.empty()) return make_error(ErrorCode::kInvalidInput, "expected a sentence, got nothing");
  if (tokens.size() > kMaxSentenceWords)
    return make_error(ErrorCode::kInvalidInput, "sentence longer than " + std::to_string(kMaxSentenceWords) + " words");
  WordSpan w(tokens);
  if (w.size() == 1 && (w[0] == "yes" || w[0] == "no")) return Answer{w[0] == "yes"};
  if (starts_with(w, {"you", "are", "done"}) && w.size() == 3) return Done{};
  if (w.size() == 1 && w[0] == "repeat") return Repeat{};
  if (w[0] == "repeat") return repeat_while(w);
  if (w[0] == "if") return goal_description(w);
  if (starts_with(w, {"the", "goal"})) return goal_statement(w, std::nullopt);
  if (auto subtask = subtask_command(w)) return *subtask;
  if (is_one_of(w[0], {"open", "close", "pick", "pick-up", "put", "put-down"})) return action(w);
  if (auto task = task_name(w)) return *task;
  return make_error(ErrorCode::kInvalidInput,
                    "expected a goal ('the goal is that ...'), an action ('open', 'close', 'pick up', 'put'), "
                    "a task or an answer, got " + quoted(phrase(w)));
}

}  // namespace apprentice::language
