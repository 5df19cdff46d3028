// Facts are ground atoms over object ids: (in ketchup1 fridge1) is
// Fact{in, {ketchup1, fridge1}}. They are small values, ordered and hashable.
#pragma once

#include <array>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>

#include "util/check.h"

namespace apprentice {

// Index of an object in a Universe (world/universe.h).
using ObjectId = std::uint32_t;
// Index of a predicate in a Domain (world/domain.h).
using PredicateId = std::uint16_t;

inline constexpr std::size_t kMaxArity = 3;

struct Fact {
  PredicateId predicate = 0;
  std::uint16_t arity = 0;
  std::array<ObjectId, kMaxArity> args{};  // unused slots stay 0

  Fact() = default;
  Fact(PredicateId p, std::initializer_list<ObjectId> arguments) : predicate(p) {
    APPRENTICE_CHECK(arguments.size() <= kMaxArity);
    for (ObjectId a : arguments) args[arity++] = a;
  }
  Fact(PredicateId p, std::span<const ObjectId> arguments) : predicate(p) {
    APPRENTICE_CHECK(arguments.size() <= kMaxArity);
    for (ObjectId a : arguments) args[arity++] = a;
  }

  std::span<const ObjectId> arguments() const { return {args.data(), arity}; }
  bool mentions(ObjectId object) const {
    for (std::uint16_t i = 0; i < arity; ++i)
      if (args[i] == object) return true;
    return false;
  }

  friend auto operator<=>(const Fact&, const Fact&) = default;
  friend bool operator==(const Fact&, const Fact&) = default;
};

std::size_t hash_value(const Fact& fact);

struct FactHash {
  std::size_t operator()(const Fact& fact) const { return hash_value(fact); }
};

// A fact that must hold (positive) or must not hold (negative).
struct Literal {
  Fact fact;
  bool positive = true;

  friend auto operator<=>(const Literal&, const Literal&) = default;
  friend bool operator==(const Literal&, const Literal&) = default;
};

}  // namespace apprentice
