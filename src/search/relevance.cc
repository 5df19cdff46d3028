#include "search/relevance.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <set>

namespace apprentice {
namespace {

bool mentions(const AtomSchema& atom, std::size_t parameter) {
  return std::find(atom.parameters.begin(), atom.parameters.end(), parameter) != atom.parameters.end();
}

std::string atom_text(const Domain& domain, const ActionSchema& schema, const AtomSchema& atom) {
  std::string out = "(" + domain.predicates[atom.predicate].name;
  for (std::uint8_t p : atom.parameters) out += " " + schema.parameters[p].name;
  return out + ")";
}

// The one-argument predicate g paired with the zero-argument predicate h,
// if h and g form a one-arm hand (condition 3 of relevance.h, without the
// initial state, which analyze_relevance checks).
std::optional<PredicateId> hand_holding_predicate(const Domain& domain, PredicateId h) {
  std::optional<PredicateId> g;
  auto count_atoms = [](const std::vector<AtomSchema>& atoms, PredicateId p) {
    return std::count_if(atoms.begin(), atoms.end(), [&](const AtomSchema& a) { return a.predicate == p; });
  };
  // The actions that delete h fix g: each adds exactly one one-argument fact.
  for (const ActionSchema& a : domain.actions) {
    if (count_atoms(a.delete_effects, h) == 0) continue;
    std::optional<PredicateId> added;
    int one_argument_adds = 0;
    for (const AtomSchema& atom : a.add_effects) {
      if (atom.parameters.size() != 1 || domain.is_static(atom.predicate)) continue;
      ++one_argument_adds;
      added = atom.predicate;
    }
    if (one_argument_adds != 1 || (g && *g != *added)) return std::nullopt;
    g = added;
  }
  if (!g || *g == h) return std::nullopt;
  for (const ActionSchema& a : domain.actions) {
    const auto adds_h = count_atoms(a.add_effects, h), deletes_h = count_atoms(a.delete_effects, h);
    const auto adds_g = count_atoms(a.add_effects, *g), deletes_g = count_atoms(a.delete_effects, *g);
    if (adds_h > 0 && deletes_h > 0) return std::nullopt;
    for (const LiteralSchema& l : a.preconditions)
      if (!l.positive && (l.atom.predicate == h || l.atom.predicate == *g)) return std::nullopt;
    auto requires_atom = [&](const AtomSchema& atom) {
      return std::any_of(a.preconditions.begin(), a.preconditions.end(), [&](const LiteralSchema& l) {
        return l.positive && l.atom.predicate == atom.predicate && l.atom.parameters == atom.parameters;
      });
    };
    if (deletes_h > 0) {
      // Takes the hand: requires h, adds exactly one g, deletes none.
      if (!requires_atom(AtomSchema{h, {}}) || adds_g != 1 || deletes_g != 0) return std::nullopt;
    } else if (adds_h > 0) {
      // Frees the hand: requires and deletes one g fact, adds none.
      if (adds_g != 0 || deletes_g != 1) return std::nullopt;
      auto deleted = std::find_if(a.delete_effects.begin(), a.delete_effects.end(),
                                  [&](const AtomSchema& atom) { return atom.predicate == *g; });
      if (!requires_atom(*deleted)) return std::nullopt;
    } else if (adds_g > 0 || deletes_g > 0) {
      return std::nullopt;  // changes g without the hand
    }
  }
  return g;
}

bool is_hand_empty_predicate(const DomainInteraction& interaction, PredicateId p) {
  return std::any_of(interaction.hands.begin(), interaction.hands.end(),
                     [&](const DomainInteraction::Hand& h) { return h.empty == p; });
}

// "table1, counter1 and 9 more"
std::string examples(const Universe& universe, const std::vector<ObjectId>& objects) {
  std::string out;
  const std::size_t shown = std::min<std::size_t>(objects.size(), 3);
  for (std::size_t i = 0; i < shown; ++i) out += (i == 0 ? "" : ", ") + universe.name(objects[i]);
  if (objects.size() > shown) out += " and " + std::to_string(objects.size() - shown) + " more";
  return out;
}

}  // namespace

DomainInteraction analyze_interaction(const Domain& domain) {
  DomainInteraction out;
  for (std::size_t p = 0; p < domain.predicates.size(); ++p) {
    const auto id = static_cast<PredicateId>(p);
    if (!domain.predicates[p].parameter_types.empty() || domain.is_static(id)) continue;
    if (auto g = hand_holding_predicate(domain, id)) out.hands.push_back({id, *g});
  }
  out.local.resize(domain.actions.size());
  out.reason.resize(domain.actions.size());
  for (std::size_t a = 0; a < domain.actions.size(); ++a) {
    const ActionSchema& schema = domain.actions[a];
    out.local[a].assign(schema.parameters.size(), true);
    out.reason[a].assign(schema.parameters.size(), "");
    for (std::size_t p = 0; p < schema.parameters.size(); ++p) {
      for (const auto* effects : {&schema.add_effects, &schema.delete_effects}) {
        for (const AtomSchema& atom : *effects) {
          if (!out.local[a][p] || mentions(atom, p)) continue;
          if (atom.parameters.empty() && is_hand_empty_predicate(out, atom.predicate)) continue;
          out.local[a][p] = false;
          out.reason[a][p] = schema.name + " changes " + atom_text(domain, schema, atom) + ", which is not about " +
                             schema.parameters[p].name;
        }
      }
    }
  }
  return out;
}

Relevance analyze_relevance(const Domain& domain, const Universe& universe, const State& state, const Goal& goal) {
  const DomainInteraction interaction = analyze_interaction(domain);
  Relevance out;
  // Sublinear in the number of objects: only the goal's objects, the ones
  // held and those of the types that fill non-local parameters are visited
  // (plus what is kept), each fact found by an indexed query.
  const std::size_t n = universe.size();
  std::set<ObjectId> keep;
  for (ObjectId o : goal.objects()) keep.insert(o);
  std::set<ObjectId> required = keep;  // kept whatever the domain says

  // Condition 3 against this state and goal: exactly one of h and the g
  // facts holds, and the goal never asks for h or g to be false.
  std::optional<std::string> off;
  for (const DomainInteraction::Hand& hand : interaction.hands) {
    std::size_t held = 0;
    for (const Fact& f : state.facts_of(hand.holding)) {
      if (f.arity == 1) {
        ++held;
        keep.insert(f.args[0]);
        required.insert(f.args[0]);
      }
    }
    const bool empty = state.holds(Fact(hand.empty, std::initializer_list<ObjectId>{}));
    if (held + (empty ? 1 : 0) != 1)
      off = "the initial state does not hold exactly one of (" + domain.predicates[hand.empty].name + ") and (" +
            domain.predicates[hand.holding].name + " ?x)";
    for (const Literal& l : goal.literals)
      if (!l.positive && (l.fact.predicate == hand.empty || l.fact.predicate == hand.holding))
        off = "the goal asks for (" + domain.predicates[l.fact.predicate].name + ") to be false";
  }
  if (off) {
    out.objects.resize(n);
    for (std::size_t o = 0; o < n; ++o) out.objects[o] = static_cast<ObjectId>(o);
    out.notes.push_back("relevance pruning is off: " + *off + ", so an object that is not in the goal may still "
                        "have to move");
    return out;
  }

  // Condition 2: every object that can fill a non-local parameter.
  for (std::size_t a = 0; a < domain.actions.size(); ++a) {
    const ActionSchema& schema = domain.actions[a];
    for (std::size_t p = 0; p < schema.parameters.size(); ++p) {
      if (interaction.local[a][p]) continue;
      std::vector<const LiteralSchema*> unary_static;
      for (const LiteralSchema& l : schema.preconditions)
        if (domain.is_static(l.atom.predicate) && l.atom.parameters.size() == 1 && l.atom.parameters[0] == p)
          unary_static.push_back(&l);
      std::vector<ObjectId> fitting;
      for (std::size_t t = 0; t < domain.types.size(); ++t)
        if (domain.is_subtype(static_cast<TypeId>(t), schema.parameters[p].type)) {
          const std::vector<ObjectId>& of_type = universe.of_type(static_cast<TypeId>(t));
          fitting.insert(fitting.end(), of_type.begin(), of_type.end());
        }
      std::sort(fitting.begin(), fitting.end());
      std::vector<ObjectId> newly_kept;
      for (ObjectId id : fitting) {
        bool fills = std::all_of(unary_static.begin(), unary_static.end(), [&](const LiteralSchema* l) {
          return state.holds(Fact(l->atom.predicate, {id})) == l->positive;
        });
        if (!fills) continue;
        if (keep.insert(id).second) newly_kept.push_back(id);
      }
      if (!newly_kept.empty())
        out.notes.push_back("relevance: keeps " + examples(universe, newly_kept) + " because " +
                            interaction.reason[a][p]);
    }
  }
  for (ObjectId o : keep) {
    out.objects.push_back(o);
    if (!required.count(o) && universe.info(o).kind == ObjectKind::kItem) ++out.kept_for_interaction;
  }
  out.pruned = n - out.objects.size();
  std::string summary = "relevance: " + std::to_string(out.objects.size()) + " of " + std::to_string(n) +
                        " objects can matter to the goal; " + std::to_string(out.pruned) + " pruned";
  if (out.pruned > 0)
    summary += ", since every action on them changes only facts about the object itself and the hand";
  if (out.kept_for_interaction > 0)
    summary += "; " + std::to_string(out.kept_for_interaction) +
               " items not in the goal are kept because they can interact with others";
  out.notes.insert(out.notes.begin(), summary);
  return out;
}

std::vector<ObjectId> relevant_objects(const Domain& domain, const Universe& universe,
                                       const State& state, const Goal& goal) {
  return analyze_relevance(domain, universe, state, goal).objects;
}

State project_state(const State& state, const std::vector<ObjectId>& objects) {
  // The facts all of whose arguments are kept: for each (predicate, arity)
  // present, those about each kept object as first argument (O(log n) each),
  // so O(predicates * objects * log n), not a scan of every fact.
  std::vector<Fact> kept;
  auto all_kept = [&](const Fact& fact) {
    for (ObjectId o : fact.arguments())
      if (!std::binary_search(objects.begin(), objects.end(), o)) return false;
    return true;
  };
  Fact at;  // the first (predicate, arity) not yet done
  for (FactRange rest = state.facts_from(at); !rest.empty(); rest = state.facts_from(at)) {
    const Fact& first = rest.front();
    at = Fact();
    at.predicate = first.predicate;
    at.arity = first.arity;
    if (first.arity == 0) {
      kept.push_back(first);
    } else {
      for (ObjectId o : objects)
        for (const Fact& fact : state.facts_of(first.predicate, first.arity, o))
          if (all_kept(fact)) kept.push_back(fact);
    }
    // Past every fact of this predicate and arity.
    if (at.arity < kMaxArity) {
      ++at.arity;
    } else if (at.predicate < std::numeric_limits<PredicateId>::max()) {
      ++at.predicate;
      at.arity = 0;
    } else {
      break;
    }
  }
  return State(std::move(kept));
}

SearchScope search_scope(const Domain& domain, const Universe& universe, const State& state, const Goal& goal,
                         bool prune) {
  SearchScope scope;
  if (prune) {
    Relevance relevance = analyze_relevance(domain, universe, state, goal);
    scope.objects = std::move(relevance.objects);
    scope.notes = std::move(relevance.notes);
    scope.state = project_state(state, scope.objects);
  } else {
    scope.objects.resize(universe.size());
    for (std::size_t i = 0; i < scope.objects.size(); ++i) scope.objects[i] = static_cast<ObjectId>(i);
    scope.state = state;
    scope.notes.push_back("relevance pruning is off: every object is ground");
  }
  return scope;
}

}  // namespace apprentice
