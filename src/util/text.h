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

// The one reading of English plurals, for matching names, never for saying.
// A noun's singular by its suffix: "toys" -> "toy", "boxes" -> "box",
// "berries" -> "berry"; "glass" and words of three letters stay.
std::string singular_noun(std::string_view word);
// A word and every singular its suffix allows, the word first: "boxes" ->
// {"boxes", "box", "boxe"}; "shelves" -> {"shelves", "shelf", "shelv",
// "shelve"}; forms of one letter are left out.
std::vector<std::string> singular_forms(std::string_view word);
// "a\"b" -> "\"a\\\"b\"": for messages that quote user input or a model's
// text, on one line: newlines, tabs and other control characters escaped
// ("\\n", "\\t", "\\x1b").
std::string quoted(std::string_view text);

}  // namespace apprentice
