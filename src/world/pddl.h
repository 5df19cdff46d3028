// Reading and writing PDDL: STRIPS with :typing, :negative-preconditions
// and :equality. Errors give source:line:column and what was expected.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "util/result.h"
#include "world/domain.h"
#include "world/goal.h"
#include "world/state.h"
#include "world/universe.h"

namespace apprentice {

Result<Domain> parse_domain(std::string_view text, std::string_view source);
Result<Domain> read_domain_file(const std::filesystem::path& path);

// A planning problem over a domain. Objects read from a problem file get
// their category from their name without its trailing digits.
struct PddlProblem {
  std::string name;
  Universe universe;
  State init;
  Goal goal;
};

Result<PddlProblem> parse_problem(const Domain& domain, std::string_view text,
                                  std::string_view source);

std::string write_domain(const Domain& domain);
std::string write_problem(std::string_view name, const Domain& domain, const Universe& universe,
                          const State& init, const Goal& goal);

// Reads a whole input file within the limits of util/file.h: kNotFound if
// it does not exist, kInvalidInput for a directory or a file too large,
// kIo (with the reason) if it cannot be read.
Result<std::string> read_text_file(const std::filesystem::path& path);

}  // namespace apprentice
