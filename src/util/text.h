// Small string helpers shared by the readers and the language module.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace apprentice {

std::string to_lower(std::string_view text);
std::string_view trim(std::string_view text);
// Splits on runs of whitespace; no empty pieces.
std::vector<std::string> split_words(std::string_view text);
std::string join(const std::vector<std::string>& pieces, std::string_view separator);
bool starts_with_ignoring_case(std::string_view text, std::string_view prefix);
// Whether `word` is one of `set`: is_one_of(w, {"the", "a", "an"}).
bool is_one_of(std::string_view word, std::initializer_list<std::string_view> set);
// "a\"b" -> "\"a\\\"b\"": for messages that quote user input or a model's
// text, on one line: newlines, tabs and other control characters escaped
// ("\\n", "\\t", "\\x1b").
std::string quoted(std::string_view text);

}  // namespace apprentice
