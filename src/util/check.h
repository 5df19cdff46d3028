// Checks for broken invariants (bugs). A failed check prints file:line and
// the condition, then aborts. Never use a check for bad input: bad input is
// an Error value (util/result.h).
#pragma once

namespace apprentice::detail {
[[noreturn]] void check_failed(const char* file, int line, const char* condition,
                               const char* message);
}  // namespace apprentice::detail

#define APPRENTICE_CHECK(condition)                                             \
  do {                                                                          \
    if (!(condition))                                                           \
      ::apprentice::detail::check_failed(__FILE__, __LINE__, #condition, nullptr); \
  } while (false)

#define APPRENTICE_CHECK_MSG(condition, message)                                \
  do {                                                                          \
    if (!(condition))                                                           \
      ::apprentice::detail::check_failed(__FILE__, __LINE__, #condition, message); \
  } while (false)
