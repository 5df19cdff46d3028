#include "language/logical_form.h"

#include <string>

#include "util/text.h"

namespace apprentice::language {
namespace {

// Quotes a phrase for the s-expression; the parser never lets a quote or a
// backslash into a word unescaped, but fuzzed input may hold anything.
std::string q(std::string_view text) { return quoted(text); }

struct FormWriter {
  std::string operator()(const TaskName& t) const { return "(task " + q(join(t.words, " ")) + ")"; }
  std::string operator()(const RepeatWhile& r) const {
    return "(repeat-while (" + std::string(to_string(r.relation)) + " " + q(r.place.text()) + "))";
  }
  std::string operator()(const SubtaskCommand& s) const {
    return "(subtask " + q(s.verb) + " (" + std::string(to_string(s.relation)) + " " +
           q(s.place.text()) + "))";
  }
  std::string operator()(const Done&) const { return "(done)"; }
  std::string operator()(const Repeat&) const { return "(repeat)"; }
  std::string operator()(const Answer& a) const { return a.yes ? "(answer yes)" : "(answer no)"; }
  std::string operator()(const GoalDescription& g) const {
    std::string out = "(goal";
    if (g.category) out += " (category " + q(g.category->text()) + ")";
    for (const Conjunct& c : g.conjuncts) out += " " + format_conjunct(c);
    return out + ")";
  }
  std::string operator()(const ActionCommand& a) const {
    std::string out = "(action " + std::string(to_string(a.verb)) + " " + q(a.object.text());
    if (a.preposition && a.destination)
      out += " (" + std::string(to_string(*a.preposition)) + " " + q(a.destination->text()) + ")";
    return out + ")";
  }
};

}  // namespace

std::string NounPhrase::text() const { return join(words, " "); }

bool NounPhrase::is_object_of_interest() const {
  return words.size() == 1 && words[0] == "object" && (article.empty() || article == "the");
}

std::string_view to_string(Relation relation) {
  switch (relation) {
    case Relation::kIn: return "in";
    case Relation::kOn: return "on";
  }
  return "in";
}

std::string_view to_string(ActionVerb verb) {
  switch (verb) {
    case ActionVerb::kOpen: return "open";
    case ActionVerb::kClose: return "close";
    case ActionVerb::kPickUp: return "pick-up";
    case ActionVerb::kPut: return "put";
  }
  return "open";
}

std::string_view to_string(ActionPreposition preposition) {
  switch (preposition) {
    case ActionPreposition::kFrom: return "from";
    case ActionPreposition::kIn: return "in";
    case ActionPreposition::kOn: return "on";
  }
  return "in";
}

std::string format_conjunct(const Conjunct& conjunct) {
  if (const auto* p = std::get_if<Placement>(&conjunct))
    return "(" + std::string(to_string(p->relation)) + " " + q(p->thing.text()) + " " +
           q(p->place.text()) + ")";
  const auto& s = std::get<PropertyStatement>(conjunct);
  switch (s.property) {
    case Property::kClosed: return "(closed " + q(s.thing.text()) + ")";
    case Property::kOpen: return "(open " + q(s.thing.text()) + ")";
    case Property::kUnknown: break;
  }
  return "(is " + q(s.thing.text()) + " " + q(join(s.words, " ")) + ")";
}

std::string format_logical_form(const LogicalForm& form) { return std::visit(FormWriter{}, form); }

}  // namespace apprentice::language
