// A small reader for the parenthesised syntax of PDDL: tokens with line and
// column, and a tree of lists and atoms. Comments start with ';'.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "util/result.h"

namespace apprentice {

struct SourcePosition {
  std::size_t line = 1;
  std::size_t column = 1;
};

struct SExpr {
  bool is_list = false;
  std::string atom;  // lower-cased; empty for lists
  std::vector<SExpr> items;
  SourcePosition position;

  bool is_atom(std::string_view text) const { return !is_list && atom == text; }
};

// Parses exactly one top-level expression (trailing comments and blanks
// allowed). Errors read "<source>:<line>:<column>: expected ...".
Result<SExpr> parse_sexpr(std::string_view text, std::string_view source);

// "<source>:<line>:<column>: <message>" as an kInvalidInput error.
Error syntax_error(std::string_view source, SourcePosition position, std::string_view message);

}  // namespace apprentice
