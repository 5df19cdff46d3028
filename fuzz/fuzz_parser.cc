// libFuzzer target for the sentence parser: any bytes must give a logical
// form or an error, never a crash, a sanitizer report or a hang; and what
// the parser returns must keep its documented invariants.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <variant>

#include "language/parser.h"

namespace {

using namespace apprentice::language;

// A violated invariant is a bug: abort so that libFuzzer reports the input.
void require(bool condition) {
  if (!condition) std::abort();
}

void check_phrase(const NounPhrase& np) {
  require(!np.words.empty());
  for (const std::string& w : np.words) require(!w.empty());
}

struct Invariants {
  void operator()(const TaskName& t) const { require(!t.words.empty()); }
  void operator()(const RepeatWhile& r) const { check_phrase(r.place); }
  void operator()(const SubtaskCommand& s) const {
    require(!s.verb.empty());
    check_phrase(s.place);
  }
  void operator()(const Done&) const {}
  void operator()(const Repeat&) const {}
  void operator()(const Answer&) const {}
  void operator()(const GoalDescription& g) const {
    require(!g.conjuncts.empty());
    if (g.category) check_phrase(*g.category);
    for (const Conjunct& c : g.conjuncts) {
      if (const auto* p = std::get_if<Placement>(&c)) {
        check_phrase(p->thing);
        check_phrase(p->place);
      } else {
        const auto& s = std::get<PropertyStatement>(c);
        check_phrase(s.thing);
        require(!s.words.empty());
      }
    }
  }
  void operator()(const ActionCommand& a) const {
    check_phrase(a.object);
    require(a.preposition.has_value() == a.destination.has_value());
    if (a.destination) check_phrase(*a.destination);
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view sentence(reinterpret_cast<const char*>(data), size);
  auto form = parse(sentence);
  if (!form) {
    require(!form.error().message.empty());
    return 0;
  }
  std::visit(Invariants{}, *form);
  std::string text = format_logical_form(*form);
  require(!text.empty() && text.front() == '(' && text.back() == ')');
  // Parsing is a function of the sentence: the same bytes, the same form.
  auto again = parse(sentence);
  require(again.has_value() && *again == *form);
  return 0;
}
