// A goal is a conjunction of literals over object ids, such as
// (and (in ketchup1 fridge1) (closed fridge1)).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "util/result.h"
#include "world/domain.h"
#include "world/fact.h"
#include "world/state.h"
#include "world/universe.h"

namespace apprentice {

struct Goal {
  std::vector<Literal> literals;  // kept sorted and without duplicates

  Goal() = default;
  explicit Goal(std::vector<Literal> literals);

  bool satisfied_by(const State& state) const;
  bool empty() const { return literals.empty(); }
  // Every object the goal mentions, sorted, without duplicates.
  std::vector<ObjectId> objects() const;

  friend bool operator==(const Goal&, const Goal&) = default;
};

// "(in ketchup1 fridge1)"
std::string format_fact(const Domain& domain, const Universe& universe, const Fact& fact);
// "(not (closed fridge1))" for a negative literal.
std::string format_literal(const Domain& domain, const Universe& universe, const Literal& literal);
// "(and (in ketchup1 fridge1) (closed fridge1))"; a one-literal goal has no "and".
std::string format_goal(const Domain& domain, const Universe& universe, const Goal& goal);

// Parses the PDDL-style text that format_goal writes, checking predicate
// names, arities and object ids. Errors name the column.
Result<Goal> parse_goal(const Domain& domain, const Universe& universe, std::string_view text);

}  // namespace apprentice
