// From sentences to logical forms. The parser knows the grammar of the
// paper's restricted English (docs/language.md) and nothing of the world:
// whether "the trash can" names anything is for language/grounding.h.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "language/logical_form.h"
#include "util/result.h"

namespace apprentice::language {

// Sentences longer than this (in bytes or words) are refused unread, so the
// parser's cost is bounded whatever it is fed.
inline constexpr std::size_t kMaxSentenceBytes = 2000;
inline constexpr std::size_t kMaxSentenceWords = 80;

// Lower-cases (ASCII), strips surrounding quotes and final punctuation
// (".", "!", "?"), splits on whitespace and makes each comma a word of its
// own: "Put X, then Y." -> {"put", "x", ",", "then", "y"}.
std::vector<std::string> tokenize(std::string_view sentence);

// Parses one sentence. Never throws and never aborts, whatever the bytes.
// On failure the error's code is kInvalidInput and its message says what
// was expected where ("expected 'that' after 'the goal is'"); the grounder
// reports such a sentence as `uninterpretable`.
Result<LogicalForm> parse(std::string_view sentence);

}  // namespace apprentice::language
