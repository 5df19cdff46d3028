#include "world/goal.h"

#include <algorithm>

#include "util/spelling.h"
#include "world/goal_reader.h"
#include "world/sexpr.h"

namespace apprentice {

Goal::Goal(std::vector<Literal> given) : literals(std::move(given)) {
  std::sort(literals.begin(), literals.end());
  literals.erase(std::unique(literals.begin(), literals.end()), literals.end());
}

bool Goal::satisfied_by(const State& state) const {
  return std::all_of(literals.begin(), literals.end(),
                     [&](const Literal& l) { return state.satisfies(l); });
}

std::vector<ObjectId> Goal::objects() const {
  std::vector<ObjectId> out;
  for (const Literal& l : literals)
    for (ObjectId o : l.fact.arguments()) out.push_back(o);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::string format_fact(const Domain& domain, const Universe& universe, const Fact& fact) {
  std::string out = "(" + domain.predicates.at(fact.predicate).name;
  for (ObjectId o : fact.arguments()) out += " " + universe.name(o);
  return out + ")";
}

std::string format_literal(const Domain& domain, const Universe& universe, const Literal& literal) {
  std::string fact = format_fact(domain, universe, literal.fact);
  return literal.positive ? fact : "(not " + fact + ")";
}

std::string format_goal(const Domain& domain, const Universe& universe, const Goal& goal) {
  if (goal.literals.size() == 1) return format_literal(domain, universe, goal.literals[0]);
  std::string out = "(and";
  for (const Literal& l : goal.literals) out += " " + format_literal(domain, universe, l);
  return out + ")";
}

std::string no_such_object(const Universe& universe, std::string_view name) {
  std::string message = "expected an object; there is no " + std::string(name);
  std::vector<std::string> ids;
  ids.reserve(universe.size());
  for (const ObjectInfo& o : universe.objects()) ids.push_back(o.id);
  if (auto near = closest_match(name, ids)) message += "; did you mean " + *near + "?";
  return message;
}

Result<Fact> fact_from_sexpr(const Domain& domain, const Universe& universe, const SExpr& expr,
                             std::string_view source) {
  if (!expr.is_list || expr.items.empty() || expr.items[0].is_list)
    return tl::unexpected(syntax_error(source, expr.position, "expected a fact such as (closed fridge1)"));
  auto predicate = domain.find_predicate(expr.items[0].atom);
  if (!predicate)
    return tl::unexpected(syntax_error(source, expr.items[0].position,
                                       "expected a predicate of domain " + domain.name + ", not " +
                                           expr.items[0].atom));
  const PredicateSchema& schema = domain.predicates[*predicate];
  if (expr.items.size() - 1 != schema.parameter_types.size())
    return tl::unexpected(syntax_error(source, expr.position,
                                       "expected " + std::to_string(schema.parameter_types.size()) +
                                           " arguments for " + schema.name));
  std::vector<ObjectId> args;
  for (std::size_t i = 1; i < expr.items.size(); ++i) {
    const SExpr& term = expr.items[i];
    if (term.is_list)
      return tl::unexpected(syntax_error(source, term.position, "expected an object name, not a list"));
    auto object = universe.find(term.atom);
    if (!object)
      return tl::unexpected(syntax_error(source, term.position, no_such_object(universe, term.atom)));
    TypeId wanted = schema.parameter_types[i - 1];
    if (!domain.is_subtype(universe.info(*object).type, wanted))
      return tl::unexpected(syntax_error(source, term.position,
                                         "expected an object of type " + type_word(domain, wanted) +
                                             "; " + term.atom + " is a " +
                                             type_word(domain, universe.info(*object).type)));
    args.push_back(*object);
  }
  return Fact(*predicate, args);
}

Result<Goal> goal_from_sexpr(const Domain& domain, const Universe& universe, const SExpr& expr,
                             std::string_view source) {
  std::vector<Literal> literals;
  std::vector<const SExpr*> parts;
  if (expr.is_list && !expr.items.empty() && expr.items[0].is_atom("and")) {
    for (std::size_t i = 1; i < expr.items.size(); ++i) parts.push_back(&expr.items[i]);
  } else {
    parts.push_back(&expr);
  }
  for (const SExpr* part : parts) {
    bool positive = true;
    const SExpr* atom = part;
    if (part->is_list && !part->items.empty() && part->items[0].is_atom("not")) {
      if (part->items.size() != 2)
        return tl::unexpected(syntax_error(source, part->position, "expected (not (FACT))"));
      positive = false;
      atom = &part->items[1];
    }
    auto fact = fact_from_sexpr(domain, universe, *atom, source);
    if (!fact) return tl::unexpected(fact.error());
    literals.push_back(Literal{*fact, positive});
  }
  if (literals.empty())
    return tl::unexpected(syntax_error(source, expr.position, "expected at least one fact in the goal"));
  return Goal(std::move(literals));
}

Result<Goal> parse_goal(const Domain& domain, const Universe& universe, std::string_view text) {
  auto expr = parse_sexpr(text, "goal");
  if (!expr) return tl::unexpected(expr.error());
  return goal_from_sexpr(domain, universe, *expr, "goal");
}

}  // namespace apprentice
