// Errors as values. Every fallible function in apprentice returns
// Result<T>; no exception escapes our code. The set of codes is small and
// closed, chosen the way abseil chooses status codes: by what the caller
// should do about it, not by where it happened.
#pragma once

#include <string>
#include <string_view>
#include <utility>

#include <tl/expected.hpp>

namespace apprentice {

enum class ErrorCode {
  // The input is malformed: a syntax error in a PDDL or YAML file, a flag
  // value that does not parse. Retrying with the same input cannot help.
  kInvalidInput,
  // A named thing does not exist: a file, an object id, a predicate.
  kNotFound,
  // The input is well formed but the system is not in a state to use it:
  // a knowledge store written by an incompatible version, say.
  kFailedPrecondition,
  // A dependency is down or answered garbage: an LLM server refusing
  // connections, answering 5xx, or sending a body we cannot decode.
  // Retrying later may help.
  kUnavailable,
  // A deadline or budget ran out before an answer arrived.
  kDeadlineExceeded,
  // Reading or writing local storage failed (disk full, permissions).
  kIo,
  // Stored data is unreadable or corrupt.
  kDataLoss,
  // The user asked to stop (end of input, interrupt).
  kCancelled,
};

std::string_view to_string(ErrorCode code);

struct Error {
  ErrorCode code;
  std::string message;

  // "invalid input: data/x.yaml:3:5: expected a mapping"
  std::string describe() const;
};

template <typename T>
using Result = tl::expected<T, Error>;

// The status of an operation that returns nothing on success.
using Status = Result<void>;

inline tl::unexpected<Error> make_error(ErrorCode code, std::string message) {
  return tl::unexpected<Error>(Error{code, std::move(message)});
}

// Adds context in front of an error's message, keeping its code:
// prefix_error(e, "loading scenario") -> "loading scenario: <message>".
inline Error prefix_error(Error error, std::string_view prefix) {
  error.message = std::string(prefix) + ": " + error.message;
  return error;
}

}  // namespace apprentice
