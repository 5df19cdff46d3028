#include "llm/cassette.h"

#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "llm/json_fields.h"
#include "util/file.h"
#include "util/log.h"

namespace apprentice::llm {
namespace {

using nlohmann::json;

std::string dump(const json& value) {
  return value.dump(-1, ' ', false, json::error_handler_t::replace);
}

json about_to_json(const QueryAbout& about) {
  json j{{"kind", to_string(about.kind)},     {"task", about.task},
         {"subtask", about.subtask},          {"object", about.object_category},
         {"place", about.place},              {"goal", about.goal},
         {"steps", about.steps_so_far},       {"action_word", about.action_word}};
  // Only re-prompts carry it, so cassettes of first queries keep their bytes.
  if (!about.rejected.empty()) j["rejected"] = about.rejected;
  // Only preference queries (llm/preference_prompts.h) carry these.
  if (!about.receptacles.empty()) j["receptacles"] = about.receptacles;
  if (!about.examples.empty()) j["examples"] = about.examples;
  if (!about.summary.empty()) j["summary"] = about.summary;
  if (!about.objects.empty()) j["objects"] = about.objects;
  return j;
}

QueryAbout about_from_json(const json& j) {
  QueryAbout about;
  auto kind = query_kind_from_string(j.at("kind").get<std::string>());
  if (!kind) throw std::runtime_error("unknown query kind");
  about.kind = *kind;
  about.task = j.value("task", "");
  about.subtask = j.value("subtask", "");
  about.object_category = j.value("object", "");
  about.place = j.value("place", "");
  about.goal = j.value("goal", "");
  about.steps_so_far = j.value("steps", std::vector<std::string>{});
  about.action_word = j.value("action_word", "");
  about.rejected = j.value("rejected", std::vector<std::string>{});
  about.receptacles = j.value("receptacles", std::vector<std::string>{});
  about.examples = j.value("examples", std::vector<std::pair<std::string, std::string>>{});
  about.summary = j.value("summary", "");
  about.objects = j.value("objects", std::vector<std::string>{});
  return about;
}

// The request without its `about`: what a server actually receives.
json request_core(const CompletionRequest& request) {
  return json{{"prompt", request.prompt},
              {"temperature", request.temperature},
              {"max_tokens", request.max_tokens},
              {"stop", request.stop},
              {"top_logprobs", request.top_logprobs}};
}

json request_to_json(const CompletionRequest& request) {
  json j = request_core(request);
  j["about"] = about_to_json(request.about);
  return j;
}

// An integer field in [low, high]; anything else makes the line unreadable.
int64_t checked_integer(const json& j, const char* key, int64_t low, int64_t high) {
  auto value = json_fields::integer_in(j.at(key), low, high);
  if (!value) throw std::runtime_error(std::string(key) + " is not an integer in range");
  return *value;
}

CompletionRequest request_from_json(const json& j) {
  CompletionRequest request;
  request.prompt = j.at("prompt").get<std::string>();
  auto temperature = json_fields::finite_number(j.at("temperature"));
  if (!temperature || *temperature < 0.0 || *temperature > 2.0)
    throw std::runtime_error("temperature is not a number from 0 to 2");
  request.temperature = *temperature;
  request.max_tokens = static_cast<int>(checked_integer(j, "max_tokens", 1, 1 << 20));
  request.stop = j.at("stop").get<std::vector<std::string>>();
  request.top_logprobs = static_cast<int>(checked_integer(j, "top_logprobs", 0, 20));
  request.about = about_from_json(j.at("about"));
  return request;
}

// [token, logprob]; an unreported logprob (NaN) is null.
json token_to_json(const TokenLogprob& token) {
  json logprob = std::isnan(token.logprob) ? json(nullptr) : json(token.logprob);
  return json::array({token.token, logprob});
}

TokenLogprob token_from_json(const json& j) {
  const json& logprob = j.at(1);
  if (logprob.is_null()) return TokenLogprob{j.at(0).get<std::string>(), std::numeric_limits<double>::quiet_NaN()};
  auto value = json_fields::finite_number(logprob);
  if (!value) throw std::runtime_error("a log-probability is neither a number nor null");
  return TokenLogprob{j.at(0).get<std::string>(), *value};
}

json completion_to_json(const Completion& completion) {
  json tokens = json::array();
  for (const TokenLogprob& token : completion.tokens) tokens.push_back(token_to_json(token));
  json top = json::array();
  for (const auto& position : completion.top_logprobs) {
    json alternatives = json::array();
    for (const TokenLogprob& token : position) alternatives.push_back(token_to_json(token));
    top.push_back(std::move(alternatives));
  }
  return json{{"answered", completion.answered},
              {"source", to_string(completion.source)},
              {"text", completion.text},
              {"tokens", std::move(tokens)},
              {"top_logprobs", std::move(top)},
              {"finish_reason", completion.finish_reason},
              {"prompt_tokens", completion.prompt_tokens},
              {"completion_tokens", completion.completion_tokens},
              {"raw", completion.raw}};
}

Completion completion_from_json(const json& j) {
  Completion completion;
  completion.answered = j.at("answered").get<bool>();
  completion.source = j.at("source").get<std::string>() == "corpus" ? ResponseSource::kCorpus
                                                                    : ResponseSource::kModel;
  completion.text = j.at("text").get<std::string>();
  for (const json& token : j.at("tokens")) completion.tokens.push_back(token_from_json(token));
  for (const json& position : j.at("top_logprobs")) {
    std::vector<TokenLogprob> alternatives;
    for (const json& token : position) alternatives.push_back(token_from_json(token));
    completion.top_logprobs.push_back(std::move(alternatives));
  }
  completion.finish_reason = j.at("finish_reason").get<std::string>();
  completion.prompt_tokens = checked_integer(j, "prompt_tokens", 0, json_fields::kMaxTokenCount);
  completion.completion_tokens = checked_integer(j, "completion_tokens", 0, json_fields::kMaxTokenCount);
  completion.raw = j.value("raw", "");
  return completion;
}

ErrorCode error_code_from_string(std::string_view text) {
  for (ErrorCode code : {ErrorCode::kInvalidInput, ErrorCode::kNotFound,
                         ErrorCode::kFailedPrecondition, ErrorCode::kUnavailable,
                         ErrorCode::kDeadlineExceeded, ErrorCode::kIo, ErrorCode::kDataLoss,
                         ErrorCode::kCancelled}) {
    if (to_string(code) == text) return code;
  }
  return ErrorCode::kUnavailable;
}

}  // namespace

std::string exchange_to_line(const Exchange& exchange) {
  json line;
  line["request"] = request_to_json(exchange.request);
  if (exchange.response) {
    line["response"] = completion_to_json(*exchange.response);
  } else {
    line["error"] = json{{"code", to_string(exchange.response.error().code)},
                         {"message", exchange.response.error().message}};
  }
  return dump(line);
}

Result<Exchange> exchange_from_line(std::string_view text) {
  try {
    json line = json::parse(text);
    Exchange exchange{request_from_json(line.at("request")), Completion{}};
    if (auto error = line.find("error"); error != line.end()) {
      exchange.response = make_error(error_code_from_string(error->at("code").get<std::string>()),
                                     error->at("message").get<std::string>());
    } else {
      exchange.response = completion_from_json(line.at("response"));
    }
    return exchange;
  } catch (const std::exception& e) {
    return make_error(ErrorCode::kDataLoss, std::string("not a cassette line: ") + e.what());
  }
}

std::string meaning_key(const QueryAbout& about) {
  json steps = json::array();
  for (const std::string& step : about.steps_so_far) steps.push_back(normalize_label(step));
  json key = json::array({to_string(about.kind), normalize_label(about.task), normalize_label(about.subtask),
                          normalize_label(about.object_category), normalize_place(about.place),
                          normalize_label(about.goal), steps, normalize_label(about.action_word)});
  if (!about.rejected.empty()) {
    json rejected = json::array();
    for (const std::string& statement : about.rejected) rejected.push_back(normalize_label(statement));
    key.push_back(rejected);
  }
  if (about.kind == QueryKind::kSummary || about.kind == QueryKind::kPlacement) {
    json receptacles = json::array(), examples = json::array(), objects = json::array();
    for (const std::string& r : about.receptacles) receptacles.push_back(normalize_label(r));
    for (const auto& [thing, place] : about.examples)
      examples.push_back(json::array({normalize_label(thing), normalize_label(place)}));
    for (const std::string& o : about.objects) objects.push_back(normalize_label(o));
    key.push_back(json::array({receptacles, examples, normalize_label(about.summary), objects}));
  }
  return dump(key);
}

// ---- RecordingClient ----

Result<std::unique_ptr<RecordingClient>> RecordingClient::open(const std::filesystem::path& path,
                                                               std::unique_ptr<LlmClient> inner) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return make_error(ErrorCode::kIo, "cannot write the cassette " + path.string());
  return std::unique_ptr<RecordingClient>(
      new RecordingClient(path, std::move(inner), std::move(out)));
}

std::string RecordingClient::describe() const {
  return "record " + path_.string() + " <- " + inner_->describe();
}

bool RecordingClient::pools_sources() const { return inner_->pools_sources(); }

Result<Completion> RecordingClient::do_complete(const CompletionRequest& request) {
  Exchange exchange{request, inner_->complete(request)};
  out_ << exchange_to_line(exchange) << '\n';
  out_.flush();
  if (!out_) {
    return make_error(ErrorCode::kIo, "cannot append to the cassette " + path_.string());
  }
  return std::move(exchange.response);
}

// ---- ReplayClient ----

ReplayClient::ReplayClient(std::filesystem::path path, std::vector<Exchange> exchanges)
    : path_(std::move(path)), exchanges_(std::move(exchanges)) {
  for (size_t i = 0; i < exchanges_.size(); ++i) {
    by_request_[dump(request_core(exchanges_[i].request))].entries.push_back(i);
    by_meaning_[meaning_key(exchanges_[i].request.about)].entries.push_back(i);
  }
}

Result<std::unique_ptr<ReplayClient>> ReplayClient::open(const std::filesystem::path& path) {
  auto file = read_input_lines(path);  // within the input limits (util/file.h)
  if (!file) return tl::unexpected(prefix_error(file.error(), "the cassette"));
  std::vector<Exchange> exchanges;
  size_t number = 0;
  for (const std::string& line : *file) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    Result<Exchange> exchange = exchange_from_line(line);
    if (!exchange) {
      return tl::unexpected(prefix_error(exchange.error(),
                                         path.string() + ":" + std::to_string(number)));
    }
    exchanges.push_back(std::move(*exchange));
  }
  return std::unique_ptr<ReplayClient>(new ReplayClient(path, std::move(exchanges)));
}

std::string ReplayClient::describe() const {
  return "replay " + path_.string() + " (" + std::to_string(exchanges_.size()) + " exchanges)";
}

Result<Completion> ReplayClient::take(Cursor& cursor) {
  const size_t index = cursor.entries[cursor.next % cursor.entries.size()];
  ++cursor.next;
  return exchanges_[index].response;
}

Result<Completion> ReplayClient::do_complete(const CompletionRequest& request) {
  if (auto exact = by_request_.find(dump(request_core(request))); exact != by_request_.end()) {
    return take(exact->second);
  }
  if (auto similar = by_meaning_.find(meaning_key(request.about)); similar != by_meaning_.end()) {
    spdlog::debug("replay: no exact match, answering by meaning ({})", to_string(request.about.kind));
    return take(similar->second);
  }
  if (!request.about.rejected.empty()) {
    // A re-prompt with the rejected answers that was not recorded (the
    // cassette comes from a run in which they were not rejected, or from
    // before re-prompting): no answer, as a corpus gives, so the run goes
    // on as it would without it.
    Completion nothing;
    nothing.answered = false;
    nothing.finish_reason = "stop";
    return nothing;
  }
  return make_error(ErrorCode::kNotFound,
                    "nothing recorded in " + path_.string() + " for this " +
                        std::string(to_string(request.about.kind)) + " query (object " +
                        request.about.object_category + ")");
}

}  // namespace apprentice::llm
