#include "llm/retrieval.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "util/check.h"
#include "util/log.h"
#include "util/text.h"

namespace apprentice::llm {
namespace {

std::string uniqueness_key(std::string_view text) { return to_lower(join(split_words(text), " ")); }

bool contains_text(const std::vector<Candidate>& candidates, std::string_view text) {
  const std::string key = uniqueness_key(text);
  return std::any_of(candidates.begin(), candidates.end(),
                     [&](const Candidate& c) { return uniqueness_key(c.text) == key; });
}

// Cuts the text at the first stop sequence (for servers that ignore "stop")
// and trims it.
std::string clean_text(std::string_view text, const std::vector<std::string>& stops) {
  size_t cut = text.size();
  for (const std::string& stop : stops) {
    if (stop.empty()) continue;
    cut = std::min(cut, text.find(stop));
  }
  return std::string(trim(text.substr(0, cut)));
}

// One query of get_unique_responses. Returns false when the retrieval must
// stop (an error, or the backend has nothing).
bool query_once(LlmClient& client, CompletionRequest& request, double temperature,
                Retrieval& out) {
  request.temperature = temperature;
  ++out.queries;
  Result<Completion> completion = client.complete(request);
  if (!completion) {
    out.failure = completion.error();
    return false;
  }
  spdlog::info("LLM {} answer at temperature {}: {}", to_string(request.about.kind), temperature,
               describe_answer(*completion));
  if (!completion->answered) {
    out.unanswered = true;
    return false;
  }
  std::string text = clean_text(completion->text, request.stop);
  if (text.empty() || contains_text(out.candidates, text)) return true;
  Candidate candidate;
  candidate.text = std::move(text);
  candidate.mean_logprob = mean_logprob(completion->tokens);
  candidate.temperature = temperature;
  candidate.source = completion->source;
  out.candidates.push_back(std::move(candidate));
  return true;
}

}  // namespace

Retrieval get_unique_responses(LlmClient& client, CompletionRequest request,
                               const UniqueResponsesParams& params) {
  APPRENTICE_CHECK(params.desired >= 1 && params.max_attempts >= 0);
  Retrieval out;
  if (!query_once(client, request, params.low_temp, out)) return out;
  int tries = 1;
  double temperature = params.high_temp;
  while (static_cast<int>(out.candidates.size()) < params.desired && tries <= params.max_attempts) {
    if (tries * 2 > params.max_attempts) temperature = params.max_temp;  // tries > max/2
    if (!query_once(client, request, temperature, out)) break;
    ++tries;
  }
  return out;
}

Retrieval retrieve_goals(LlmClient& client, const PromptTemplates& templates,
                         const TaskContext& context, const GoalParams& params) {
  CompletionRequest request;
  request.prompt = templates.goal_prompt(context);
  request.max_tokens = params.max_tokens;
  request.stop = params.stop;
  request.top_logprobs = 1;
  request.about = about_for(context, QueryKind::kGoal);
  Retrieval out = get_unique_responses(client, std::move(request), params.unique);
  if (out.failure) spdlog::info("LLM goal retrieval failed: {}", out.failure->describe());
  return out;
}

std::string join_action(std::string_view word, std::string_view completion) {
  std::string text(trim(word));
  if (!completion.empty() && std::isalnum(static_cast<unsigned char>(completion.front()))) {
    text.push_back(' ');
  }
  text.append(completion);
  return join(split_words(text), " ");
}

namespace {

// The words of Algorithm 3's first step that pass their threshold, most
// probable first, trimmed and without repeats.
std::vector<TokenLogprob> kept_words(const std::vector<TokenLogprob>& words,
                                     const IsKnownActionWord& is_known, const ActionParams& params) {
  std::vector<TokenLogprob> kept;
  std::vector<std::string> seen;
  for (const TokenLogprob& word : words) {
    std::string text(trim(word.token));
    // A step starts with a word: a quote or a dash a chat model opens its
    // answer with ("\"", p = 0.72) is no action, however probable.
    if (std::none_of(text.begin(), text.end(), [](char c) { return std::isalpha(static_cast<unsigned char>(c)); }))
      continue;
    if (std::find(seen.begin(), seen.end(), to_lower(text)) != seen.end()) continue;
    seen.push_back(to_lower(text));
    // A word whose probability the server did not report is the model's own
    // choice at temperature 0: kept, since no threshold can be checked.
    if (std::isnan(word.logprob)) {
      kept.push_back(TokenLogprob{text, word.logprob});
      continue;
    }
    const bool known = is_known && is_known(text);
    const double threshold = known ? params.known_word_threshold : params.unknown_word_threshold;
    if (std::exp(word.logprob) >= threshold) kept.push_back(TokenLogprob{text, word.logprob});
  }
  return kept;
}

}  // namespace

Retrieval retrieve_actions(LlmClient& client, const PromptTemplates& templates,
                           const TaskContext& context, std::string_view goal,
                           std::span<const std::string> steps_so_far,
                           const IsKnownActionWord& is_known_action_word,
                           const ActionParams& params) {
  Retrieval out;
  const std::string prompt = templates.action_prompt(context, goal, steps_so_far);
  QueryAbout about = about_for(context, QueryKind::kActionWord);
  about.goal = std::string(goal);
  about.steps_so_far.assign(steps_so_far.begin(), steps_so_far.end());

  ++out.queries;
  auto words = next_token_alternatives(client, prompt, params.num_words, about);
  if (!words) {
    out.failure = words.error();
    spdlog::info("LLM action retrieval failed: {}", out.failure->describe());
    return out;
  }
  out.first_words = *words;
  out.unanswered = words->empty();
  if (spdlog::should_log(spdlog::level::info)) {
    std::string listed;
    for (const TokenLogprob& word : *words)
      listed += (listed.empty() ? "" : ", ") + apprentice::quoted(word.token) +
                (std::isnan(word.logprob) ? std::string(" (p unknown)") : fmt::format(" (p {:.3f})", std::exp(word.logprob)));
    spdlog::info("LLM first words: {}", listed.empty() ? std::string("none") : listed);
  }
  for (const TokenLogprob& word : kept_words(*words, is_known_action_word, params)) {
    CompletionRequest request;
    request.prompt = prompt + " " + word.token;
    request.max_tokens = params.max_tokens;
    request.stop = params.stop;
    request.top_logprobs = 1;
    request.about = about;
    request.about.kind = QueryKind::kAction;
    request.about.action_word = word.token;
    Retrieval completions = get_unique_responses(client, std::move(request), params.unique);
    out.queries += completions.queries;
    for (Candidate& candidate : completions.candidates) {
      candidate.text = join_action(word.token, candidate.text);
      if (contains_text(out.candidates, candidate.text)) continue;
      candidate.action_word = word.token;
      candidate.action_word_prob = std::exp(word.logprob);
      out.candidates.push_back(std::move(candidate));
    }
    if (completions.failure) {
      out.failure = completions.failure;
      spdlog::info("LLM action retrieval failed: {}", out.failure->describe());
      break;
    }
  }
  return out;
}

void sort_by_mean_logprob(std::vector<Candidate>& candidates) {
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    if (!b.mean_logprob) return a.mean_logprob.has_value();
    return a.mean_logprob && *a.mean_logprob > *b.mean_logprob;
  });
}

Result<Choice> finalize_choice(std::vector<Candidate> candidates, QueryKind kind, const Grounds& grounds,
                               Confirmer* confirmer, const ChoiceOptions& options) {
  if (options.sort_by_probability) sort_by_mean_logprob(candidates);
  auto does_ground = [&](const Candidate& c) { return !grounds || grounds(c); };
  Choice choice;
  if (confirmer == nullptr) {
    for (const Candidate& candidate : candidates) {
      const bool grounded = does_ground(candidate);
      if (options.unattended == UnattendedPolicy::kFirstGrounded && !grounded) {
        ++choice.skipped_ungrounded;
        continue;
      }
      choice.origin = ChoiceOrigin::kUnconfirmed;
      choice.text = candidate.text;
      choice.candidate = candidate;
      choice.grounded = grounded;
      return choice;
    }
    return choice;  // kNone
  }
  for (const Candidate& candidate : candidates) {
    const bool grounded = does_ground(candidate);
    if (!grounded && !options.offer_ungrounded) {
      ++choice.skipped_ungrounded;
      continue;
    }
    ++choice.offered;
    Result<bool> accepted = confirmer->confirm(kind, candidate);
    if (!accepted) return tl::unexpected(accepted.error());
    if (*accepted) {
      choice.origin = ChoiceOrigin::kConfirmed;
      choice.text = candidate.text;
      choice.candidate = candidate;
      choice.grounded = grounded;
      return choice;
    }
    choice.rejected.push_back(candidate);
  }
  if (!options.ask_description) return choice;  // kNone: the caller goes on
  Result<std::optional<std::string>> described = confirmer->describe(kind);
  if (!described) return tl::unexpected(described.error());
  if (described->has_value()) {
    choice.origin = ChoiceOrigin::kInstructor;
    choice.text = **described;
  }
  return choice;
}

Result<Choice> finalize_choice(std::vector<Candidate> candidates, QueryKind kind,
                               const Grounds& grounds, Confirmer* confirmer,
                               UnattendedPolicy policy) {
  ChoiceOptions options;
  options.unattended = policy;
  return finalize_choice(std::move(candidates), kind, grounds, confirmer, options);
}

}  // namespace apprentice::llm
