#include "llm/llm_client.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>

#include "util/check.h"
#include "util/log.h"
#include "util/text.h"

namespace apprentice::llm {

std::string_view to_string(QueryKind kind) {
  switch (kind) {
    case QueryKind::kGoal: return "goal";
    case QueryKind::kActionWord: return "action_word";
    case QueryKind::kAction: return "action";
    case QueryKind::kSummary: return "summary";
    case QueryKind::kPlacement: return "placement";
  }
  return "goal";
}

std::optional<QueryKind> query_kind_from_string(std::string_view text) {
  for (QueryKind kind : {QueryKind::kGoal, QueryKind::kActionWord, QueryKind::kAction, QueryKind::kSummary,
                         QueryKind::kPlacement}) {
    if (to_string(kind) == text) return kind;
  }
  return std::nullopt;
}

std::string_view to_string(ResponseSource source) {
  return source == ResponseSource::kCorpus ? "corpus" : "model";
}

bool operator==(const TokenLogprob& a, const TokenLogprob& b) {
  // Two unreported log-probabilities (NaN) are the same value here, so that
  // a replayed completion compares equal to the recorded one.
  const bool same_value =
      (std::isnan(a.logprob) && std::isnan(b.logprob)) || a.logprob == b.logprob;
  return a.token == b.token && same_value;
}

std::optional<double> mean_logprob(const std::vector<TokenLogprob>& tokens) {
  double sum = 0.0;
  int count = 0;
  for (const TokenLogprob& token : tokens) {
    if (!std::isfinite(token.logprob)) continue;
    sum += token.logprob;
    ++count;
  }
  if (count == 0) return std::nullopt;
  return sum / count;
}

LogprobsArrived logprobs_arrived(const Completion& completion) {
  if (completion.text.empty() && completion.tokens.empty()) return LogprobsArrived::kNoText;
  return mean_logprob(completion.tokens) ? LogprobsArrived::kYes : LogprobsArrived::kNo;
}

std::string describe_answer(const Completion& completion) {
  if (!completion.answered) return "(nothing for this query)";
  switch (logprobs_arrived(completion)) {
    case LogprobsArrived::kNoText: return "(no text)";
    case LogprobsArrived::kNo: return apprentice::quoted(completion.text) + " (no log-probabilities)";
    case LogprobsArrived::kYes: break;
  }
  // Tokens of the text: an end-of-sequence entry has none.
  int reported = 0, spelled = 0;
  for (const TokenLogprob& token : completion.tokens) {
    if (token.token.empty() && !std::isfinite(token.logprob)) continue;
    ++spelled;
    reported += std::isfinite(token.logprob) ? 1 : 0;
  }
  char mean[32];
  std::snprintf(mean, sizeof mean, "%.3f", *mean_logprob(completion.tokens));
  return apprentice::quoted(completion.text) + " (mean log-probability " + mean + " over " +
         std::to_string(reported) + " of " + std::to_string(spelled) + " tokens)";
}

Result<Completion> LlmClient::complete(const CompletionRequest& request) {
  // Malformed requests come from our own code, not from users: abort.
  APPRENTICE_CHECK(request.max_tokens >= 1);
  APPRENTICE_CHECK(request.temperature >= 0.0 && request.temperature <= 2.0);
  APPRENTICE_CHECK(request.top_logprobs >= 0 && request.top_logprobs <= 20);
  ++usage_.queries;
  Result<Completion> result = do_complete(request);
  if (!result) {
    ++usage_.failures;
    spdlog::debug("llm {} query failed: {}", to_string(request.about.kind),
                  result.error().describe());
    return result;
  }
  if (!result->answered) ++usage_.unanswered;
  usage_.prompt_tokens += result->prompt_tokens;
  usage_.completion_tokens += result->completion_tokens;
  return result;
}

Result<std::vector<TokenLogprob>> next_token_alternatives(LlmClient& client,
                                                          std::string prompt, int k,
                                                          QueryAbout about) {
  APPRENTICE_CHECK(k >= 1);
  CompletionRequest request;
  request.prompt = std::move(prompt);
  request.temperature = 0.0;
  request.max_tokens = 1;
  request.top_logprobs = k;
  request.about = std::move(about);
  Result<Completion> completion = client.complete(request);
  if (!completion) return tl::unexpected(completion.error());
  if (!completion->answered) return std::vector<TokenLogprob>{};
  if (!completion->top_logprobs.empty() && !completion->top_logprobs.front().empty()) {
    std::vector<TokenLogprob> alternatives = completion->top_logprobs.front();
    if (static_cast<int>(alternatives.size()) > k) alternatives.resize(k);
    return alternatives;
  }
  if (!completion->tokens.empty()) return std::vector<TokenLogprob>{completion->tokens.front()};
  // A server that reports no log-probabilities at all ("logprobs": null):
  // the one token generated is the text, its probability unknown.
  if (!completion->text.empty())
    return std::vector<TokenLogprob>{TokenLogprob{completion->text, std::numeric_limits<double>::quiet_NaN()}};
  return std::vector<TokenLogprob>{};
}

std::string normalize_label(std::string_view text) {
  std::string out;
  bool pending_space = false;
  for (char raw : text) {
    char c = raw == '-' || raw == '_' ? ' ' : raw;
    if (std::isspace(static_cast<unsigned char>(c))) {
      pending_space = !out.empty();
      continue;
    }
    if (pending_space) out.push_back(' ');
    pending_space = false;
    out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  }
  return out;
}

std::string normalize_place(std::string_view text) {
  std::string place = normalize_label(text);
  for (std::string_view prefix : {"on the ", "in the ", "at the ", "on ", "in ", "at ", "the "}) {
    if (place.size() > prefix.size() && place.compare(0, prefix.size(), prefix) == 0) {
      return place.substr(prefix.size());
    }
  }
  return place;
}

}  // namespace apprentice::llm
