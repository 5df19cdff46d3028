#include <algorithm>
#include <cctype>
#include <map>

#include "world/goal_reader.h"
#include "world/pddl.h"
#include "world/sexpr.h"

namespace apprentice {

namespace {

std::string write_atom_schema(const Domain& domain, const ActionSchema& action, const AtomSchema& atom) {
  std::string out = "(" + domain.predicates[atom.predicate].name;
  for (std::uint8_t p : atom.parameters) out += " " + action.parameters[p].name;
  return out + ")";
}

std::string type_suffix(const Domain& domain, TypeId type) {
  // Without :typing every name is an object, and a typed list would not
  // read back ("typed names need :typing"; found by fuzz_pddl).
  const auto& r = domain.requirements;
  if (std::find(r.begin(), r.end(), "typing") == r.end()) return "";
  return " - " + domain.types[type].name;
}

}  // namespace

std::string write_domain(const Domain& domain) {
  std::string out = "(define (domain " + domain.name + ")\n  (:requirements";
  for (const std::string& r : domain.requirements) out += " :" + r;
  out += ")\n";
  if (domain.types.size() > 1) {
    out += "  (:types";
    for (std::size_t t = 1; t < domain.types.size(); ++t)
      out += " " + domain.types[t].name + type_suffix(domain, domain.types[t].parent);
    out += ")\n";
  }
  out += "  (:predicates\n";
  for (const PredicateSchema& p : domain.predicates) {
    out += "    (" + p.name;
    for (std::size_t i = 0; i < p.parameter_types.size(); ++i)
      out += " ?x" + std::to_string(i) + type_suffix(domain, p.parameter_types[i]);
    out += ")\n";
  }
  out += "  )\n";
  for (const ActionSchema& a : domain.actions) {
    out += "  (:action " + a.name + "\n    :parameters (";
    for (std::size_t i = 0; i < a.parameters.size(); ++i)
      out += (i ? " " : "") + a.parameters[i].name + type_suffix(domain, a.parameters[i].type);
    out += ")\n    :precondition (and";
    for (const EqualitySchema& e : a.equalities) {
      std::string eq = "(= " + a.parameters[e.left].name + " " + a.parameters[e.right].name + ")";
      out += " " + (e.positive ? eq : "(not " + eq + ")");
    }
    for (const LiteralSchema& l : a.preconditions) {
      std::string atom = write_atom_schema(domain, a, l.atom);
      out += " " + (l.positive ? atom : "(not " + atom + ")");
    }
    out += ")\n    :effect (and";
    for (const AtomSchema& e : a.add_effects) out += " " + write_atom_schema(domain, a, e);
    for (const AtomSchema& e : a.delete_effects) out += " (not " + write_atom_schema(domain, a, e) + ")";
    out += "))\n";
  }
  return out + ")\n";
}

std::string write_problem(std::string_view name, const Domain& domain, const Universe& universe,
                          const State& init, const Goal& goal) {
  std::string out = "(define (problem " + std::string(name) + ")\n  (:domain " + domain.name +
                    ")\n  (:objects\n";
  std::map<TypeId, std::vector<std::string>> by_type;
  for (const ObjectInfo& o : universe.objects()) by_type[o.type].push_back(o.id);
  for (const auto& [type, names] : by_type) {
    out += "   ";
    for (const std::string& n : names) out += " " + n;
    out += type_suffix(domain, type) + "\n";
  }
  out += "  )\n  (:init\n";
  for (const Fact& f : init.facts()) out += "    " + format_fact(domain, universe, f) + "\n";
  out += "  )\n  (:goal (and";
  for (const Literal& l : goal.literals) out += " " + format_literal(domain, universe, l);
  return out + "))\n)\n";
}

namespace {

std::string category_from_name(const std::string& name) {
  std::size_t end = name.size();
  while (end > 0 && std::isdigit(static_cast<unsigned char>(name[end - 1]))) --end;
  return end == 0 ? name : name.substr(0, end);
}

// Objects of a problem file are places if their type says so, so that
// search (relevance pruning) treats them as it treats a scenario's places.
ObjectKind kind_of_type(const Domain& domain, TypeId type) {
  for (ObjectKind kind : {ObjectKind::kReceptacle, ObjectKind::kSurface}) {
    auto kind_type = domain.find_type(type_name(kind));
    if (kind_type && domain.is_subtype(type, *kind_type)) return kind;
  }
  return ObjectKind::kItem;
}

Status read_objects(const Domain& domain, const SExpr& section, Universe& universe,
                    std::string_view source) {
  std::vector<const SExpr*> pending;
  auto flush = [&](TypeId type) -> Status {
    for (const SExpr* n : pending) {
      if (universe.find(n->atom)) return tl::unexpected(syntax_error(source, n->position, "object " + n->atom + " is declared twice"));
      universe.add(ObjectInfo{n->atom, category_from_name(n->atom), kind_of_type(domain, type), type, {}});
    }
    pending.clear();
    return {};
  };
  for (std::size_t i = 1; i < section.items.size(); ++i) {
    const SExpr& item = section.items[i];
    if (item.is_list) return tl::unexpected(syntax_error(source, item.position, "expected an object name"));
    if (item.atom != "-") {
      pending.push_back(&item);
      continue;
    }
    if (i + 1 >= section.items.size() || section.items[i + 1].is_list)
      return tl::unexpected(syntax_error(source, item.position, "expected a type after '-'"));
    auto type = domain.find_type(section.items[i + 1].atom);
    if (!type) return tl::unexpected(syntax_error(source, section.items[i + 1].position, "expected a declared type, not " + section.items[i + 1].atom));
    auto status = flush(*type);
    if (!status) return status;
    ++i;
  }
  return flush(kRootType);
}

}  // namespace

Result<PddlProblem> parse_problem(const Domain& domain, std::string_view text, std::string_view source) {
  auto top = parse_sexpr(text, source);
  if (!top) return tl::unexpected(top.error());
  if (!top->is_list || top->items.size() < 2 || !top->items[0].is_atom("define") ||
      !top->items[1].is_list || top->items[1].items.size() != 2 ||
      !top->items[1].items[0].is_atom("problem"))
    return tl::unexpected(syntax_error(source, top->position, "expected (define (problem NAME) ...)"));
  PddlProblem problem;
  problem.name = top->items[1].items[1].atom;
  std::vector<Fact> init;
  bool has_goal = false;
  for (std::size_t i = 2; i < top->items.size(); ++i) {
    const SExpr& section = top->items[i];
    if (!section.is_list || section.items.empty() || section.items[0].is_list)
      return tl::unexpected(syntax_error(source, section.position, "expected a section such as (:init ...)"));
    const std::string& key = section.items[0].atom;
    if (key == ":domain") {
      if (section.items.size() != 2 || section.items[1].atom != domain.name)
        return tl::unexpected(syntax_error(source, section.position, "expected (:domain " + domain.name + ")"));
    } else if (key == ":objects") {
      auto status = read_objects(domain, section, problem.universe, source);
      if (!status) return tl::unexpected(status.error());
    } else if (key == ":init") {
      for (std::size_t j = 1; j < section.items.size(); ++j) {
        auto fact = fact_from_sexpr(domain, problem.universe, section.items[j], source);
        if (!fact) return tl::unexpected(fact.error());
        init.push_back(*fact);
      }
    } else if (key == ":goal") {
      if (section.items.size() != 2)
        return tl::unexpected(syntax_error(source, section.position, "expected (:goal CONDITION)"));
      auto goal = goal_from_sexpr(domain, problem.universe, section.items[1], source);
      if (!goal) return tl::unexpected(goal.error());
      problem.goal = std::move(*goal);
      has_goal = true;
    } else {
      return tl::unexpected(syntax_error(source, section.items[0].position,
                                         "expected :domain, :objects, :init or :goal, not " + key));
    }
  }
  if (!has_goal) return tl::unexpected(syntax_error(source, top->position, "expected a (:goal ...) section"));
  problem.init = State(std::move(init));
  return problem;
}

}  // namespace apprentice
