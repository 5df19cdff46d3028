// Internal to the agent: how a step of a teaching session ends early.
//
// A step either runs to its end or stops: with an error (the teacher left,
// the store failed), or with none when an undo put the session back at an
// earlier point and the loop should simply go on from there. The parts a
// session delegates to (agent/actor.h) stop the same way, so that an undo
// said in the middle of their work reaches the session's loop unchanged.
#pragma once

#include <optional>

#include "util/result.h"

namespace apprentice {

struct Stop {
  std::optional<Error> error;  // none: an undo restored an earlier point
};

template <typename T>
using Flow = tl::expected<T, Stop>;

inline tl::unexpected<Stop> stop(Error error) { return tl::unexpected<Stop>(Stop{std::move(error)}); }

}  // namespace apprentice
