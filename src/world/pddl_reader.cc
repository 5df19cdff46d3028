#include <algorithm>

#include "util/file.h"
#include "world/pddl.h"
#include "world/sexpr.h"

namespace apprentice {

Result<std::string> read_text_file(const std::filesystem::path& path) { return read_input_file(path); }

namespace {

const char* const kSupportedRequirements[] = {"strips", "typing", "negative-preconditions",
                                              "equality"};

class DomainReader {
 public:
  explicit DomainReader(std::string_view source) : source_(source) {}

  Result<Domain> read(const SExpr& top) {
    if (!top.is_list || top.items.empty() || !top.items[0].is_atom("define"))
      return fail(top, "expected (define (domain NAME) ...)");
    if (top.items.size() < 2 || !top.items[1].is_list || top.items[1].items.size() != 2 ||
        !top.items[1].items[0].is_atom("domain") || top.items[1].items[1].is_list)
      return fail(top.items.size() < 2 ? top : top.items[1], "expected (domain NAME)");
    domain_.name = top.items[1].items[1].atom;
    for (std::size_t i = 2; i < top.items.size(); ++i) {
      const SExpr& section = top.items[i];
      if (!section.is_list || section.items.empty() || section.items[0].is_list)
        return fail(section, "expected a section such as (:predicates ...) or (:action ...)");
      const std::string& key = section.items[0].atom;
      Status status;
      if (key == ":requirements") status = read_requirements(section);
      else if (key == ":types") status = read_types(section);
      else if (key == ":predicates") status = read_predicates(section);
      else if (key == ":action") status = read_action(section);
      else
        return fail(section.items[0], "expected :requirements, :types, :predicates or :action, not " +
                                          key + " (not supported)");
      if (!status) return tl::unexpected(status.error());
    }
    domain_.static_predicates.assign(domain_.predicates.size(), true);
    for (const ActionSchema& action : domain_.actions) {
      for (const AtomSchema& a : action.add_effects) domain_.static_predicates[a.predicate] = false;
      for (const AtomSchema& a : action.delete_effects) domain_.static_predicates[a.predicate] = false;
    }
    return std::move(domain_);
  }

 private:
  tl::unexpected<Error> fail(const SExpr& at, std::string_view message) const {
    return tl::unexpected(syntax_error(source_, at.position, message));
  }
  bool has_requirement(std::string_view r) const {
    return std::find(domain_.requirements.begin(), domain_.requirements.end(), r) !=
           domain_.requirements.end();
  }

  Status read_requirements(const SExpr& section) {
    for (std::size_t i = 1; i < section.items.size(); ++i) {
      const SExpr& item = section.items[i];
      if (item.is_list || item.atom.size() < 2 || item.atom[0] != ':')
        return fail(item, "expected a requirement such as :strips");
      std::string name = item.atom.substr(1);
      if (std::find(std::begin(kSupportedRequirements), std::end(kSupportedRequirements), name) ==
          std::end(kSupportedRequirements))
        return fail(item, "expected :strips, :typing, :negative-preconditions or :equality; :" +
                              name + " is not supported");
      domain_.requirements.push_back(name);
    }
    return {};
  }

  // Reads "a b - parent c" lists; calls add(name, type_atom_or_empty, at).
  template <typename Add>
  Status read_typed_list(const SExpr& list, std::size_t first, Add add) {
    std::vector<const SExpr*> pending;
    for (std::size_t i = first; i < list.items.size(); ++i) {
      const SExpr& item = list.items[i];
      if (item.is_list) return fail(item, "expected a name, not a list");
      if (item.atom == "-") {
        // "a - - b": the second '-' is not a type name (found by fuzz_pddl).
        if (i + 1 >= list.items.size() || list.items[i + 1].is_list || list.items[i + 1].atom == "-")
          return fail(item, "expected a type name after '-'");
        if (pending.empty()) return fail(item, "expected a name before '-'");
        for (const SExpr* name : pending) {
          auto status = add(*name, &list.items[i + 1]);
          if (!status) return status;
        }
        pending.clear();
        ++i;
      } else {
        pending.push_back(&item);
      }
    }
    for (const SExpr* name : pending) {
      auto status = add(*name, nullptr);
      if (!status) return status;
    }
    return {};
  }

  Result<TypeId> resolve_type(const SExpr* type_atom) const {
    if (type_atom == nullptr) return kRootType;
    if (!has_requirement("typing")) return fail(*type_atom, "typed names need :typing in :requirements");
    auto type = domain_.find_type(type_atom->atom);
    if (!type) return fail(*type_atom, "expected a declared type, not " + type_atom->atom);
    return *type;
  }

  Status read_types(const SExpr& section) {
    if (!has_requirement("typing")) return fail(section, ":types needs :typing in :requirements");
    // Two passes, so that a parent may be declared after its child.
    std::vector<std::pair<const SExpr*, const SExpr*>> declared;
    auto status = read_typed_list(section, 1, [&](const SExpr& name, const SExpr* parent) -> Status {
      if (name.atom == "object") return {};
      if (domain_.find_type(name.atom)) return fail(name, "type " + name.atom + " is declared twice");
      domain_.types.push_back(TypeInfo{name.atom, kRootType});
      declared.emplace_back(&name, parent);
      return {};
    });
    if (!status) return status;
    for (auto [name, parent] : declared) {
      if (parent == nullptr) continue;
      auto parent_type = domain_.find_type(parent->atom);
      if (!parent_type) {
        // An undeclared parent is declared implicitly, as most planners do.
        domain_.types.push_back(TypeInfo{parent->atom, kRootType});
        parent_type = static_cast<TypeId>(domain_.types.size() - 1);
      }
      TypeId self = *domain_.find_type(name->atom);
      if (domain_.is_subtype(*parent_type, self)) return fail(*parent, "type hierarchy has a cycle");
      domain_.types[self].parent = *parent_type;
    }
    return {};
  }

  Status read_predicates(const SExpr& section) {
    for (std::size_t i = 1; i < section.items.size(); ++i) {
      const SExpr& p = section.items[i];
      if (!p.is_list || p.items.empty() || p.items[0].is_list)
        return fail(p, "expected a predicate declaration such as (on ?o - item ?s - surface-place)");
      PredicateSchema schema{p.items[0].atom, {}};
      if (domain_.find_predicate(schema.name))
        return fail(p.items[0], "predicate " + schema.name + " is declared twice");
      auto status = read_typed_list(p, 1, [&](const SExpr& var, const SExpr* type) -> Status {
        if (var.atom.empty() || var.atom[0] != '?') return fail(var, "expected a variable such as ?o");
        auto t = resolve_type(type);
        if (!t) return tl::unexpected(t.error());
        schema.parameter_types.push_back(*t);
        return {};
      });
      if (!status) return status;
      if (schema.parameter_types.size() > kMaxArity)
        return fail(p, "predicates with more than " + std::to_string(kMaxArity) +
                           " arguments are not supported");
      domain_.predicates.push_back(std::move(schema));
    }
    return {};
  }

  Status read_action(const SExpr& section) {
    if (section.items.size() < 2 || section.items[1].is_list)
      return fail(section, "expected an action name after :action");
    ActionSchema action;
    action.name = section.items[1].atom;
    if (domain_.find_action(action.name)) return fail(section.items[1], "action " + action.name + " is declared twice");
    for (std::size_t i = 2; i < section.items.size(); i += 2) {
      const SExpr& key = section.items[i];
      if (key.is_list || i + 1 >= section.items.size())
        return fail(key, "expected :parameters, :precondition or :effect followed by a list");
      const SExpr& value = section.items[i + 1];
      Status status;
      if (key.atom == ":parameters") status = read_parameters(value, action);
      else if (key.atom == ":precondition") status = read_condition(value, action);
      else if (key.atom == ":effect") status = read_effect(value, action);
      else return fail(key, "expected :parameters, :precondition or :effect, not " + key.atom);
      if (!status) return status;
    }
    domain_.actions.push_back(std::move(action));
    return {};
  }

  Status read_parameters(const SExpr& list, ActionSchema& action) {
    if (!list.is_list) return fail(list, "expected a parameter list such as (?o - item)");
    auto status = read_typed_list(list, 0, [&](const SExpr& var, const SExpr* type) -> Status {
      if (var.atom.empty() || var.atom[0] != '?') return fail(var, "expected a variable such as ?o");
      for (const Parameter& p : action.parameters)
        if (p.name == var.atom) return fail(var, "parameter " + var.atom + " is declared twice");
      auto t = resolve_type(type);
      if (!t) return tl::unexpected(t.error());
      action.parameters.push_back(Parameter{var.atom, *t});
      return {};
    });
    if (!status) return status;
    if (action.parameters.size() > kMaxParameters)
      return fail(list, "actions with more than " + std::to_string(kMaxParameters) +
                            " parameters are not supported");
    return {};
  }

  Result<std::uint8_t> parameter_index(const SExpr& term, const ActionSchema& action) const {
    if (term.is_list) return fail(term, "expected a parameter such as ?o, not a list");
    for (std::size_t i = 0; i < action.parameters.size(); ++i)
      if (action.parameters[i].name == term.atom) return static_cast<std::uint8_t>(i);
    if (!term.atom.empty() && term.atom[0] == '?')
      return fail(term, "expected a parameter of the action; " + term.atom + " is not one");
    return fail(term, "expected a parameter such as ?o; constants are not supported");
  }

  Result<AtomSchema> read_atom(const SExpr& atom, const ActionSchema& action) const {
    if (!atom.is_list || atom.items.empty() || atom.items[0].is_list)
      return fail(atom, "expected an atom such as (holding ?o)");
    auto predicate = domain_.find_predicate(atom.items[0].atom);
    if (!predicate) return fail(atom.items[0], "expected a declared predicate, not " + atom.items[0].atom);
    const PredicateSchema& schema = domain_.predicates[*predicate];
    if (atom.items.size() - 1 != schema.parameter_types.size())
      return fail(atom, "expected " + std::to_string(schema.parameter_types.size()) +
                            " arguments for " + schema.name);
    AtomSchema out{*predicate, {}};
    for (std::size_t i = 1; i < atom.items.size(); ++i) {
      auto index = parameter_index(atom.items[i], action);
      if (!index) return tl::unexpected(index.error());
      TypeId param_type = action.parameters[*index].type;
      TypeId wanted = schema.parameter_types[i - 1];
      if (!domain_.is_subtype(param_type, wanted) && !domain_.is_subtype(wanted, param_type))
        return fail(atom.items[i], "expected an argument of type " + domain_.types[wanted].name +
                                       "; " + atom.items[i].atom + " is a " +
                                       domain_.types[param_type].name);
      out.parameters.push_back(*index);
    }
    return out;
  }

  // A conjunction of literals, equalities and their negations.
  Status read_condition(const SExpr& gd, ActionSchema& action) {
    if (!gd.is_list) return fail(gd, "expected a condition such as (and ...)");
    if (gd.items.empty()) return {};
    if (gd.items[0].is_atom("and")) {
      for (std::size_t i = 1; i < gd.items.size(); ++i) {
        auto status = read_condition(gd.items[i], action);
        if (!status) return status;
      }
      return {};
    }
    bool positive = true;
    const SExpr* inner = &gd;
    if (gd.items[0].is_atom("not")) {
      if (gd.items.size() != 2) return fail(gd, "expected (not (ATOM))");
      inner = &gd.items[1];
      positive = false;
      if (!inner->is_list || inner->items.empty())
        return fail(*inner, "expected an atom inside (not ...)");
    }
    if (inner->items[0].is_atom("=")) {
      if (!has_requirement("equality")) return fail(*inner, "(= ...) needs :equality in :requirements");
      if (inner->items.size() != 3) return fail(*inner, "expected (= ?a ?b)");
      auto left = parameter_index(inner->items[1], action);
      if (!left) return tl::unexpected(left.error());
      auto right = parameter_index(inner->items[2], action);
      if (!right) return tl::unexpected(right.error());
      action.equalities.push_back(EqualitySchema{*left, *right, positive});
      return {};
    }
    if (inner->items[0].is_atom("or") || inner->items[0].is_atom("imply") ||
        inner->items[0].is_atom("forall") || inner->items[0].is_atom("exists"))
      return fail(*inner, "expected a literal; " + inner->items[0].atom + " is not supported in STRIPS");
    if (!positive && !has_requirement("negative-preconditions"))
      return fail(gd, "(not ...) in a precondition needs :negative-preconditions in :requirements");
    auto atom = read_atom(*inner, action);
    if (!atom) return tl::unexpected(atom.error());
    action.preconditions.push_back(LiteralSchema{std::move(*atom), positive});
    return {};
  }

  Status read_effect(const SExpr& effect, ActionSchema& action) {
    if (!effect.is_list) return fail(effect, "expected an effect such as (and ...)");
    if (effect.items.empty()) return {};
    if (effect.items[0].is_atom("and")) {
      for (std::size_t i = 1; i < effect.items.size(); ++i) {
        auto status = read_effect(effect.items[i], action);
        if (!status) return status;
      }
      return {};
    }
    if (effect.items[0].is_atom("not")) {
      if (effect.items.size() != 2) return fail(effect, "expected (not (ATOM))");
      auto atom = read_atom(effect.items[1], action);
      if (!atom) return tl::unexpected(atom.error());
      action.delete_effects.push_back(std::move(*atom));
      return {};
    }
    if (effect.items[0].is_atom("when") || effect.items[0].is_atom("forall"))
      return fail(effect, "expected a literal; " + effect.items[0].atom + " effects are not supported");
    auto atom = read_atom(effect, action);
    if (!atom) return tl::unexpected(atom.error());
    action.add_effects.push_back(std::move(*atom));
    return {};
  }

  std::string_view source_;
  Domain domain_;
};

}  // namespace

Result<Domain> parse_domain(std::string_view text, std::string_view source) {
  auto top = parse_sexpr(text, source);
  if (!top) return tl::unexpected(top.error());
  return DomainReader(source).read(*top);
}

Result<Domain> read_domain_file(const std::filesystem::path& path) {
  auto text = read_text_file(path);
  if (!text) return tl::unexpected(text.error());
  return parse_domain(*text, path.string());
}

}  // namespace apprentice
