// The reviewed note every golden file carries (tests/<module>/golden/*).
//
// A golden file's expectations are written, or first written, by the code
// (APPRENTICE_UPDATE_GOLDEN=1), so a test that compares against them proves
// only that the code still does what it did. The note is what makes them
// expectations: a person read the file and says why it is right. It is the
// file's first block of `#` lines, up to the first blank line, and it holds
// these fields, each at the start of a line after "# ":
//
//   Reviewed:   who and when (a date YYYY-MM-DD)
//   Covers:     what the file covers
//   Source:     where its expectations come from
//   Why right:  why they are right
//   Read:       how many cases were read
//   Found:      what the reading found (wrong expectations, known wrong readings)
//   Hand check: one case derived by hand from the paper or the instructor script
//
// GoldenNotes.EveryGoldenFileHasAReviewedNote (language_tests) fails for a
// golden file without one, so a new golden file cannot come without its
// note. The update paths keep the note and print golden_update_reminder.
#pragma once

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace apprentice::testing {

inline constexpr std::string_view kGoldenNoteFields[] = {"Reviewed:", "Covers:", "Source:", "Why right:",
                                                         "Read:",     "Found:",  "Hand check:"};

// Splits a golden file's text into its note (the leading `#` lines and the
// blank line after them) and the rest. No note (an empty first part) when
// the text does not start with `#` lines followed by a blank line.
inline std::pair<std::string, std::string> split_golden_note(const std::string& text) {
  std::size_t at = 0;
  while (at < text.size() && text[at] == '#') {
    std::size_t end = text.find('\n', at);
    if (end == std::string::npos) return {"", text};
    at = end + 1;
  }
  if (at == 0 || at >= text.size() || text[at] != '\n') return {"", text};
  return {text.substr(0, at + 1), text.substr(at + 1)};
}

inline bool has_date(std::string_view line) {
  for (std::size_t i = 0; i + 10 <= line.size(); ++i) {
    std::string_view s = line.substr(i, 10);
    bool ok = true;
    for (std::size_t k = 0; k < 10 && ok; ++k)
      ok = (k == 4 || k == 7) ? s[k] == '-' : std::isdigit(static_cast<unsigned char>(s[k])) != 0;
    if (ok) return true;
  }
  return false;
}

// What the note of a golden file's text lacks: empty when the note is
// complete; every field when there is no note.
inline std::vector<std::string> golden_note_missing(const std::string& text) {
  std::string note = split_golden_note(text).first;
  std::vector<std::string> missing;
  for (std::string_view field : kGoldenNoteFields) {
    bool found = false;
    std::size_t at = 0;
    while (!found && at < note.size()) {
      std::size_t end = note.find('\n', at);
      std::string_view line(note.data() + at, end - at);
      at = end + 1;
      if (line.substr(0, 2) == "# " && line.substr(2, field.size()) == field)
        found = field != "Reviewed:" || has_date(line);
    }
    if (!found) missing.emplace_back(field);
  }
  return missing;
}

// Whether this run rewrites the golden files (APPRENTICE_UPDATE_GOLDEN=1).
inline bool golden_update_requested() {
  const char* value = std::getenv("APPRENTICE_UPDATE_GOLDEN");
  return value != nullptr && std::string_view(value) == "1";
}

// Printed whenever APPRENTICE_UPDATE_GOLDEN=1 rewrites a golden file.
inline std::string golden_update_reminder(const std::filesystem::path& path) {
  return "[ golden   ] rewrote " + path.string() +
         "\n[ golden   ] now read `git diff " + path.string() +
         "` case by case against the paper or the instructor script, and update the reviewed note at the top of "
         "the file (Reviewed:, Read:, Found:) before committing; the note was kept, not rewritten.\n";
}

}  // namespace apprentice::testing
