#include "llm/preference_prompts.h"

#include <algorithm>
#include <cctype>

#include "util/file.h"
#include "util/text.h"

namespace apprentice::llm {

namespace {

// The template's text without its single final newline (data/prompts/README.md).
Result<std::string> read_template(const std::filesystem::path& path) {
  auto text = read_input_file(path);
  if (!text) return tl::unexpected(prefix_error(text.error(), "the prompt template"));
  std::string out = std::move(*text);
  if (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

// Every {placeholder} of `text` is one of `allowed`, and each of `required` is there.
Status check_placeholders(const std::string& text, const std::filesystem::path& path,
                          std::initializer_list<std::string_view> allowed,
                          std::initializer_list<std::string_view> required) {
  for (std::size_t open = text.find('{'); open != std::string::npos; open = text.find('{', open + 1)) {
    const std::size_t close = text.find('}', open);
    if (close == std::string::npos) break;
    const std::string name = text.substr(open + 1, close - open - 1);
    if (std::find(allowed.begin(), allowed.end(), name) == allowed.end())
      return make_error(ErrorCode::kInvalidInput, path.string() + ": unknown placeholder {" + name + "}");
  }
  for (std::string_view name : required)
    if (text.find("{" + std::string(name) + "}") == std::string::npos)
      return make_error(ErrorCode::kInvalidInput, path.string() + ": the template needs {" + std::string(name) + "}");
  return {};
}

std::string fill(std::string text, std::string_view name, std::string_view value) {
  const std::string slot = "{" + std::string(name) + "}";
  for (std::size_t at = text.find(slot); at != std::string::npos; at = text.find(slot, at + value.size()))
    text.replace(at, slot.size(), value);
  return text;
}

std::vector<std::string> lines_of(std::string_view text) {
  std::vector<std::string> lines(1);
  for (char c : text) {
    if (c == '\n') lines.emplace_back();
    else if (c != '\r') lines.back() += c;
  }
  return lines;
}

std::string examples_text(const std::vector<ThingPlace>& examples) {
  std::vector<std::string> parts;
  for (const auto& [thing, place] : examples) parts.push_back(thing + " -> " + place);
  return join(parts, "; ");
}

// The thing and the place a line states, in its own words; nothing when
// it states none.
std::optional<ThingPlace> split_line(std::string_view line) {
  std::string text(trim(line));
  if (auto call = text.find("pick_and_place("); call != std::string::npos) text = text.substr(call + 15);
  for (std::string_view arrow : {"->", "=>", ":", "\t", "\",", "', "}) {
    const std::size_t at = text.find(arrow);
    if (at != std::string::npos && at > 0) return ThingPlace{text.substr(0, at), text.substr(at + arrow.size())};
  }
  // "Put the sweater in the basket."
  std::string lower = to_lower(text);
  if (lower.starts_with("put ")) {
    for (std::string_view preposition : {" in the ", " on the ", " into the ", " onto the ", " in ", " on "}) {
      const std::size_t at = lower.find(preposition);
      if (at != std::string::npos) return ThingPlace{text.substr(4, at - 4), text.substr(at + preposition.size())};
    }
  }
  return std::nullopt;
}

// The one of `names` whose key is `key`, else the one whose key the key
// contains or is contained in (the longest such), else nothing. ("bin 1"
// and "bin 12" both hold "bin 1": the whole key wins before a part.)
std::optional<std::string> match_name(const std::string& key, const std::vector<std::string>& names, NameOf of) {
  if (key.empty()) return std::nullopt;
  const std::string* partial = nullptr;
  for (const std::string& name : names) {
    const std::string k = name_key(name, of);
    if (k == key) return name;
    if (!k.empty() && (key.find(k) != std::string::npos || k.find(key) != std::string::npos))
      if (partial == nullptr || name_key(*partial, of).size() < k.size()) partial = &name;
  }
  return partial ? std::optional<std::string>(*partial) : std::nullopt;
}

}  // namespace

std::string name_key(std::string_view name, NameOf of) {
  std::string cleaned;
  for (char c : name) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (c == '\'') continue;
    cleaned += std::isalnum(u) || u >= 0x80 ? static_cast<char>(std::tolower(u)) : ' ';
  }
  std::vector<std::string> words = split_words(cleaned);
  if (!words.empty() && words.front() == "the") words.erase(words.begin());
  if (of == NameOf::kThing && words.size() > 1 && std::all_of(words.back().begin(), words.back().end(), [](char c) { return c >= '0' && c <= '9'; }))
    words.pop_back();
  return join(words, " ");
}

Result<PreferencePrompts> PreferencePrompts::load(const std::filesystem::path& dir) {
  auto summary = read_template(dir / "summary.txt");
  if (!summary) return tl::unexpected(summary.error());
  auto placement = read_template(dir / "placement.txt");
  if (!placement) return tl::unexpected(placement.error());
  if (auto s = check_placeholders(*summary, dir / "summary.txt", {"receptacles", "examples"}, {"receptacles", "examples"}); !s)
    return tl::unexpected(s.error());
  if (auto s = check_placeholders(*placement, dir / "placement.txt", {"receptacles", "knowledge", "objects"},
                                  {"receptacles", "knowledge", "objects"});
      !s)
    return tl::unexpected(s.error());
  return PreferencePrompts(std::move(*summary), std::move(*placement));
}

CompletionRequest PreferencePrompts::summary_request(const std::vector<std::string>& receptacles,
                                                     const std::vector<ThingPlace>& examples) const {
  CompletionRequest request;
  request.prompt = fill(fill(summary_, "receptacles", join(receptacles, ", ")), "examples", examples_text(examples));
  request.max_tokens = 120;
  request.stop = {"\n"};
  request.about.kind = QueryKind::kSummary;
  request.about.receptacles = receptacles;
  request.about.examples = examples;
  return request;
}

CompletionRequest PreferencePrompts::placement_request(const std::vector<std::string>& receptacles,
                                                       const std::string& summary,
                                                       const std::vector<ThingPlace>& examples,
                                                       const std::vector<std::string>& objects) const {
  std::string knowledge;
  if (!summary.empty()) knowledge = "Rule: " + summary;
  else if (!examples.empty()) knowledge = "Examples: " + examples_text(examples) + ".";
  std::string prompt = fill(placement_, "receptacles", join(receptacles, ", "));
  prompt = fill(fill(prompt, "knowledge", knowledge), "objects", join(objects, ", "));
  CompletionRequest request;
  request.prompt = std::move(prompt);
  request.max_tokens = static_cast<int>(16 * objects.size() + 16);
  request.stop = {"\n\n"};
  request.about.kind = QueryKind::kPlacement;
  request.about.receptacles = receptacles;
  request.about.summary = summary;
  if (summary.empty()) request.about.examples = examples;
  request.about.objects = objects;
  return request;
}

std::string read_summary(std::string_view completion) {
  for (const std::string& line : lines_of(completion)) {
    std::string text(trim(line));
    for (std::string_view label : {"rule:", "summary:"})
      if (starts_with_ignoring_case(text, label)) text = std::string(trim(text.substr(label.size())));
    if (!text.empty()) return text;
  }
  return {};
}

std::vector<ThingPlace> read_placements(std::string_view completion, const std::vector<std::string>& objects,
                                        const std::vector<std::string>& receptacles) {
  std::vector<ThingPlace> out;
  for (const std::string& line : lines_of(completion)) {
    auto said = split_line(line);
    if (!said) continue;
    auto thing = match_name(name_key(said->first), objects, NameOf::kThing);
    auto place = match_name(name_key(said->second, NameOf::kPlace), receptacles, NameOf::kPlace);
    if (!thing || !place) continue;
    if (std::any_of(out.begin(), out.end(), [&](const ThingPlace& p) { return p.first == *thing; })) continue;
    out.emplace_back(*thing, *place);
  }
  return out;
}

}  // namespace apprentice::llm
