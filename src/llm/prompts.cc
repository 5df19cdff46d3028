#include "llm/prompts.h"

#include <map>
#include <set>
#include <vector>

#include "util/file.h"
#include "util/text.h"


namespace apprentice::llm {
namespace {

using Values = std::map<std::string, std::string, std::less<>>;

Result<std::string> read_template(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    return make_error(ErrorCode::kNotFound, "prompt template not found: " + path.string());
  }
  auto text = read_input_file(path);  // within the input limits (util/file.h)
  if (!text) return tl::unexpected(prefix_error(text.error(), "prompt template"));
  std::string content = std::move(*text);
  // The file's final newline is an editor convention, not part of the prompt.
  if (!content.empty() && content.back() == '\n') content.pop_back();
  if (!content.empty() && content.back() == '\r') content.pop_back();
  return content;
}

// The names of the {placeholders} in `text`.
std::set<std::string> placeholders(std::string_view text) {
  std::set<std::string> names;
  size_t pos = 0;
  while ((pos = text.find('{', pos)) != std::string_view::npos) {
    size_t end = text.find('}', pos);
    if (end == std::string_view::npos) break;
    names.emplace(text.substr(pos + 1, end - pos - 1));
    pos = end + 1;
  }
  return names;
}

// Replaces each {name} by its value in one pass, so that values are never
// expanded again (an object called "{goal}" stays as it is).
std::string fill(std::string_view text, const Values& values) {
  std::string out;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t open = text.find('{', pos);
    size_t close = open == std::string_view::npos ? open : text.find('}', open);
    if (close == std::string_view::npos) break;
    auto value = values.find(text.substr(open + 1, close - open - 1));
    out.append(text.substr(pos, open - pos));
    if (value == values.end()) {
      out.append(text.substr(open, close - open + 1));
    } else {
      out.append(value->second);
    }
    pos = close + 1;
  }
  if (pos < text.size()) out.append(text.substr(pos));
  return out;
}

Status check_placeholders(std::string_view name, std::string_view text,
                          const std::set<std::string>& allowed,
                          const std::set<std::string>& required) {
  std::set<std::string> found = placeholders(text);
  for (const std::string& placeholder : found) {
    if (!allowed.contains(placeholder)) {
      return make_error(ErrorCode::kInvalidInput,
                        std::string(name) + ": unknown placeholder {" + placeholder + "}");
    }
  }
  for (const std::string& placeholder : required) {
    if (!found.contains(placeholder)) {
      return make_error(ErrorCode::kInvalidInput,
                        std::string(name) + ": missing placeholder {" + placeholder + "}");
    }
  }
  return {};
}

Values task_values(const TaskContext& context) {
  return Values{{"task", context.task},
                {"location", context.location},
                {"object", context.object},
                {"object_location", context.object_location}};
}

}  // namespace

QueryAbout about_for(const TaskContext& context, QueryKind kind) {
  QueryAbout about;
  about.kind = kind;
  about.task = context.task;
  about.subtask = context.subtask;
  about.object_category = context.object;
  about.place = normalize_place(context.object_location);
  if (kind == QueryKind::kGoal) about.rejected = context.rejected;
  return about;
}

Result<PromptTemplates> PromptTemplates::load(const std::filesystem::path& dir) {
  auto examples = read_template(dir / "examples.txt");
  if (!examples) return tl::unexpected(examples.error());
  auto goal = read_template(dir / "goal.txt");
  if (!goal) return tl::unexpected(goal.error());
  auto action = read_template(dir / "action.txt");
  if (!action) return tl::unexpected(action.error());

  const std::set<std::string> task_slots = {"task", "location", "object", "object_location"};
  std::set<std::string> goal_slots = task_slots;
  goal_slots.insert("examples");
  std::set<std::string> action_slots = goal_slots;
  action_slots.insert({"goal", "steps"});
  if (auto s = check_placeholders("examples.txt", *examples, {}, {}); !s) {
    return tl::unexpected(s.error());
  }
  if (auto s = check_placeholders("goal.txt", *goal, goal_slots, goal_slots); !s) {
    return tl::unexpected(s.error());
  }
  if (auto s = check_placeholders("action.txt", *action, action_slots, action_slots); !s) {
    return tl::unexpected(s.error());
  }
  // Fill in the examples now; the remaining placeholders are per query.
  const Values with_examples{{"examples", *examples}};
  return PromptTemplates(fill(*goal, with_examples), fill(*action, with_examples));
}

std::string PromptTemplates::goal_prompt(const TaskContext& context) const {
  std::string prompt = fill(goal_, task_values(context));
  if (context.rejected.empty()) return prompt;
  std::string failures;
  for (const std::string& rejected : context.rejected) {
    std::string_view statement = trim(rejected);
    constexpr std::string_view kLead = "the goal is that ";
    if (starts_with_ignoring_case(statement, kLead)) statement.remove_prefix(kLead.size());
    while (!statement.empty() && statement.back() == '.') statement.remove_suffix(1);
    failures += "Not: " + std::string(statement) + ".\n";
  }
  const size_t last_line = prompt.rfind('\n');
  prompt.insert(last_line == std::string::npos ? 0 : last_line + 1, failures);
  return prompt;
}

std::string PromptTemplates::action_prompt(const TaskContext& context, std::string_view goal,
                                           std::span<const std::string> steps_so_far) const {
  std::string steps;
  for (size_t i = 0; i < steps_so_far.size(); ++i) {
    steps += std::to_string(i + 1) + ". " + std::string(trim(steps_so_far[i])) + "\n";
  }
  steps += std::to_string(steps_so_far.size() + 1) + ".";
  Values values = task_values(context);
  values.emplace("goal", std::string(goal));
  values.emplace("steps", std::move(steps));
  return fill(action_, values);
}

}  // namespace apprentice::llm
