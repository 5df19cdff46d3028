#include "fake_llm_server.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace apprentice::testing {

namespace {

using nlohmann::json;

std::vector<std::string> words_of(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The last line of the prompt's (TASK) part, after `marker`, up to the end of the line.
std::string after_last(const std::string& prompt, const std::string& marker, const std::string& end) {
  size_t at = prompt.rfind(marker);
  if (at == std::string::npos) return "";
  at += marker.size();
  size_t stop = prompt.find(end, at);
  return prompt.substr(at, stop == std::string::npos ? std::string::npos : stop - at);
}

// What the object of the prompt is: "Aware of ketchup on table." -> "ketchup".
std::string category_of(const std::string& prompt) {
  std::string aware = after_last(prompt, "Aware of ", "\n");
  return aware.substr(0, aware.find(' '));
}

// The usual steps towards the goal of an action prompt: the receptacle is
// what follows "is in the", and a door is opened first and closed last
// when the goal says "is closed".
std::vector<std::string> usual_steps(const std::string& prompt, bool with_article) {
  std::string goal = after_last(prompt, "(RESULT)", "(END RESULT)");
  std::string object = category_of(prompt);
  std::string receptacle = after_last(goal, "is in the ", " and");
  const std::string the = with_article ? "the " : "";
  std::vector<std::string> steps;
  bool door = goal.find(" is closed") != std::string::npos;
  if (door) steps.push_back("Open " + the + receptacle);
  steps.push_back("Pick up " + the + object);
  steps.push_back("Put " + the + object + " in " + the + receptacle);
  if (door) steps.push_back("Close " + the + receptacle);
  return steps;
}

// The number the prompt's next step has: "...\n2." -> 2, "...\n2. Open" -> 2.
int next_step_number(const std::string& prompt) {
  size_t line = prompt.rfind('\n');
  std::string last = prompt.substr(line == std::string::npos ? 0 : line + 1);
  int n = 0;
  for (char c : last) {
    if (!std::isdigit(static_cast<unsigned char>(c))) break;
    n = n * 10 + (c - '0');
  }
  return n;
}

}  // namespace

// What the model says: the text, its tokens with one log-probability each,
// and alternatives for the first token.
struct FakeLlmServer::Answer {
  std::string text;
  std::vector<std::string> tokens;
  double logprob = 0.0;
  std::vector<std::pair<std::string, double>> alternatives;
  int prompt_tokens = 0;
  // How it ended: at a stop string, at the end of the sequence, or at max_tokens.
  enum class End { kStop, kEndOfSequence, kLength } end = End::kStop;
};

namespace {

json usage(const FakeLlmServer::Answer& a) {
  return json{{"prompt_tokens", a.prompt_tokens},
              {"completion_tokens", static_cast<int>(a.tokens.size())},
              {"total_tokens", a.prompt_tokens + static_cast<int>(a.tokens.size())}};
}

// The alternatives at position i, the chosen token first.
std::vector<std::pair<std::string, double>> alternatives_at(const FakeLlmServer::Answer& a, size_t i) {
  std::vector<std::pair<std::string, double>> out = {{a.tokens[i], a.logprob}};
  if (i == 0)
    for (const auto& alternative : a.alternatives)
      if (alternative.first != a.tokens[i]) out.push_back(alternative);
  return out;
}

// OpenAI's legacy completions layout.
json as_completion(const FakeLlmServer::Answer& a) {
  json token_logprobs = json::array(), top = json::array();
  for (size_t i = 0; i < a.tokens.size(); ++i) {
    token_logprobs.push_back(a.logprob);
    json position = json::object();
    for (const auto& [token, lp] : alternatives_at(a, i)) position[token] = lp;
    top.push_back(position);
  }
  return json{{"id", "cmpl-fake"},
              {"object", "text_completion"},
              {"model", "fake-davinci"},
              {"choices", json::array({json{{"text", a.text},
                                            {"index", 0},
                                            {"finish_reason", "stop"},
                                            {"logprobs", json{{"tokens", a.tokens},
                                                              {"token_logprobs", token_logprobs},
                                                              {"top_logprobs", top}}}}})},
              {"usage", usage(a)}};
}

json bytes_of(const std::string& text) {
  json out = json::array();
  for (unsigned char c : text) out.push_back(static_cast<int>(c));
  return out;
}

bool has_multibyte(const std::string& text) {
  return std::any_of(text.begin(), text.end(), [](char c) { return static_cast<unsigned char>(c) >= 0x80; });
}

// Per-token entries, as OpenAI's chat and llama-server send them; with
// `quirks`, as llama-server really does (LlamaQuirks).
json entries(const FakeLlmServer::Answer& a, const char* top_key, const LlamaQuirks& quirks) {
  json content = json::array();
  size_t count = a.tokens.size();
  if (quirks.on && a.end == FakeLlmServer::Answer::End::kStop && count > 0) --count;  // the stop drops the last
  for (size_t i = 0; i < count; ++i) {
    json top = json::array();
    for (const auto& [token, lp] : alternatives_at(a, i)) top.push_back(json{{"token", token}, {"logprob", lp}});
    json entry{{"token", a.tokens[i]}, {"logprob", a.logprob}, {top_key, top}};
    if (quirks.on) {
      entry["bytes"] = bytes_of(a.tokens[i]);
      if (has_multibyte(a.tokens[i])) {
        // The last byte's log-probability, and the last byte as alternative.
        const std::string last(1, a.tokens[i].back());
        entry["logprob"] = -6.0;
        entry[top_key] = json::array({json{{"token", ""}, {"bytes", bytes_of(last)}, {"logprob", -6.0}}});
      }
    }
    content.push_back(entry);
  }
  if (quirks.on && a.end == FakeLlmServer::Answer::End::kEndOfSequence)
    content.push_back(json{{"token", ""}, {"bytes", json::array()}, {"logprob", -9.0},
                           {top_key, json::array({json{{"token", ""}, {"bytes", json::array()}, {"logprob", -9.0}}})}});
  return content;
}

// OpenAI's chat completions layout. llama-server leaves "logprobs" out when
// it has no entry.
json as_chat(const FakeLlmServer::Answer& a, const LlamaQuirks& quirks) {
  json choice{{"index", 0},
              {"message", json{{"role", "assistant"}, {"content", a.text}}},
              {"finish_reason", a.end == FakeLlmServer::Answer::End::kLength ? "length" : "stop"}};
  json content = entries(a, "top_logprobs", quirks);
  if (!quirks.on || !content.empty()) choice["logprobs"] = json{{"content", content}};
  return json{{"id", "chatcmpl-fake"},
              {"object", "chat.completion"},
              {"model", "fake-chat"},
              {"choices", json::array({choice})},
              {"usage", usage(a)}};
}

// llama-server's /v1/completions layout: its own entries under
// logprobs.content, null when it has none.
json as_llama_completion(const FakeLlmServer::Answer& a, const LlamaQuirks& quirks) {
  json content = entries(a, "top_logprobs", quirks);
  return json{{"id", "cmpl-fake"},
              {"object", "text_completion"},
              {"model", "fake-llama"},
              {"choices", json::array({json{{"text", a.text},
                                            {"index", 0},
                                            {"finish_reason", a.end == FakeLlmServer::Answer::End::kLength ? "length" : "stop"},
                                            {"logprobs", content.empty() ? json(nullptr) : json{{"content", content}}}}})},
              {"usage", usage(a)}};
}

// llama-server's /completion layout.
json as_llama(const FakeLlmServer::Answer& a, const LlamaQuirks& quirks) {
  const char* stop_type = a.end == FakeLlmServer::Answer::End::kLength          ? "limit"
                          : a.end == FakeLlmServer::Answer::End::kEndOfSequence ? "eos"
                                                                               : "word";
  json body{{"content", a.text},
            {"stop", true},
            {"stop_type", stop_type},
            {"tokens_evaluated", a.prompt_tokens},
            {"tokens_predicted", static_cast<int>(a.tokens.size())}};
  json content = entries(a, "top_logprobs", quirks);
  if (!quirks.on || !content.empty()) body["completion_probabilities"] = content;
  return body;
}

}  // namespace

FakeLlmServer::FakeLlmServer(ServerMode mode, Goals goals, std::vector<std::string> fallback, Goals second_thoughts)
    : mode_(mode), goals_(std::move(goals)), fallback_(std::move(fallback)), second_thoughts_(std::move(second_thoughts)) {
  server_.set_tcp_nodelay(true);  // no Nagle delay between headers and body
  server_.Post("/v1/completions", [this](const httplib::Request& request, httplib::Response& response) {
    handle(Dialect::kCompletions, request, response);
  });
  server_.Post("/v1/chat/completions", [this](const httplib::Request& request, httplib::Response& response) {
    handle(Dialect::kChat, request, response);
  });
  server_.Post("/completion", [this](const httplib::Request& request, httplib::Response& response) {
    handle(Dialect::kLlama, request, response);
  });
  port_ = server_.bind_to_any_port("127.0.0.1");
  if (port_ <= 0) throw std::runtime_error("cannot bind a port for the fake LLM server");
  thread_ = std::thread([this] { server_.listen_after_bind(); });
  while (!server_.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

FakeLlmServer::~FakeLlmServer() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  released_.notify_all();
  server_.stop();
  if (thread_.joinable()) thread_.join();
}

void FakeLlmServer::pause(std::chrono::milliseconds limit) {
  std::unique_lock lock(mutex_);
  released_.wait_for(lock, limit, [this] { return stopping_; });
}

std::vector<std::string> FakeLlmServer::bodies() {
  std::lock_guard lock(mutex_);
  return bodies_;
}

std::vector<std::string> FakeLlmServer::goal_prompts() {
  std::lock_guard lock(mutex_);
  return goal_prompts_;
}

void FakeLlmServer::handle(Dialect dialect, const httplib::Request& request, httplib::Response& response) {
  const int n = ++requests_;
  {
    std::lock_guard lock(mutex_);
    bodies_.push_back(request.body);
  }
  if (!required_key_.empty() && request.get_header_value("Authorization") != "Bearer " + required_key_) {
    response.status = 401;
    response.set_content(R"({"error": {"message": "Incorrect API key provided", "type": "invalid_request_error"}})",
                         "application/json");
    return;
  }
  if (!served_model_.empty()) {
    json asked = json::parse(request.body, nullptr, false);
    const std::string model = asked.is_object() ? asked.value("model", "") : "";
    if (model != served_model_) {
      response.status = 404;
      response.set_content(json{{"object", "error"},
                                {"message", "The model `" + model + "` does not exist."},
                                {"type", "NotFoundError"},
                                {"code", 404}}
                               .dump(),
                           "application/json");
      return;
    }
  }
  const bool healthy = n <= healthy_for_ || (broken_until_ > 0 && n > broken_until_);
  switch (healthy ? ServerMode::kModel : mode_) {
    case ServerMode::kStatus500:
      response.status = 500;
      response.set_content(R"({"error": {"message": "the model is overloaded"}})", "application/json");
      return;
    case ServerMode::kRateLimited:
      response.status = 429;
      response.set_header("Retry-After", "1");
      response.set_content(R"({"error": {"message": "rate limit reached"}})", "application/json");
      return;
    case ServerMode::kRateLimitedOnce:
      if (n % 2 == 1) {
        response.status = 429;
        response.set_header("Retry-After", "1");
        response.set_content(R"({"error": {"message": "rate limit reached"}})", "application/json");
        return;
      }
      break;
    case ServerMode::kSlow:
      pause(std::chrono::seconds(1));
      break;
    case ServerMode::kMalformedJson:
      response.set_content(R"({"choices": [{"text": " The goal is that the)", "application/json");
      return;
    case ServerMode::kWrongJson:
      response.set_content(R"({"object": "list", "data": []})", "application/json");
      return;
    case ServerMode::kModel:
      break;
  }
  json body = json::parse(request.body, nullptr, false);
  std::string prompt;
  int max_tokens = 16, logprobs = 1;
  if (!body.is_discarded() && body.is_object()) {
    if (dialect == Dialect::kChat && body.contains("messages") && body["messages"].is_array() &&
        !body["messages"].empty())
      prompt = body["messages"].back().value("content", "");
    if (dialect != Dialect::kChat) prompt = body.value("prompt", "");
    max_tokens = dialect == Dialect::kLlama ? body.value("n_predict", 16) : body.value("max_tokens", 16);
    logprobs = dialect == Dialect::kChat    ? body.value("top_logprobs", 1)
               : dialect == Dialect::kLlama ? body.value("n_probs", 1)
                                            : body.value("logprobs", 1);
  }
  if (prompt.empty()) {
    response.status = 400;
    response.set_content(R"({"error": {"message": "expected a completion request"}})", "application/json");
    return;
  }
  Answer answer = model_answer(prompt, body.value("temperature", 0.0), max_tokens, logprobs);
  if (quote_first_ && dialect == Dialect::kChat && max_tokens == 1) {
    // A chat model's answer opens with a quote, the step's word below it.
    answer.alternatives = {{"\"", std::log(0.72)}, {answer.tokens.front(), std::log(0.2)}};
    answer.tokens = {"\""};
    answer.text = "\"";
    answer.logprob = std::log(0.72);
  }
  if (llama_quirks_.on && prompt == "Hello") answer = Answer{"", {}, 0.0, {}, 1, Answer::End::kStop};  // the stop came first
  const LlamaQuirks& quirks = llama_quirks_;
  json reply = dialect == Dialect::kChat    ? as_chat(answer, quirks)
               : dialect == Dialect::kLlama ? as_llama(answer, quirks)
               : quirks.on                  ? as_llama_completion(answer, quirks)
                                            : as_completion(answer);
  response.set_content(reply.dump(), "application/json");
}

FakeLlmServer::Answer FakeLlmServer::model_answer(const std::string& prompt, double temperature, int max_tokens,
                                                  int logprobs) {
  const int prompt_tokens = static_cast<int>(words_of(prompt).size());
  int asked = 0;
  {
    std::lock_guard lock(mutex_);
    asked = asked_[prompt]++;
  }
  const std::string category = category_of(prompt);
  if (ends_with(prompt, "(RESULT)")) {
    {
      std::lock_guard lock(mutex_);
      goal_prompts_.push_back(prompt);
    }
    // A goal: the listed statements in order, the first at temperature 0;
    // after a rejection ("Not: ..." in the prompt), the second thoughts.
    auto found = goals_.find(category);
    std::vector<std::string> choices = found != goals_.end() ? found->second : fallback_;
    if (auto second = second_thoughts_.find(category);
        second != second_thoughts_.end() && prompt.find("\nNot: ") != std::string::npos)
      choices = second->second;
    size_t index = temperature == 0.0 ? 0 : static_cast<size_t>(asked) % choices.size();
    std::string text = " " + replace_all(choices[index], "X", category);
    std::vector<std::string> tokens;
    for (const std::string& w : words_of(text)) tokens.push_back(" " + w);
    // At temperature 0 it ends at the end of the sequence, above at the stop string.
    return Answer{text, tokens, -0.2 * static_cast<double>(index + 1), {}, prompt_tokens,
                  temperature == 0.0 ? Answer::End::kEndOfSequence : Answer::End::kStop};
  }
  const int number = next_step_number(prompt);
  std::vector<std::string> steps = usual_steps(prompt, false);
  const std::string& step = steps[std::min<size_t>(static_cast<size_t>(std::max(number - 1, 0)), steps.size() - 1)];
  const std::string word = step.substr(0, step.find(' '));
  if (max_tokens == 1) {
    // The first word of the next step, with four alternatives below the
    // agent's threshold for known words.
    std::vector<std::pair<std::string, double>> alternatives = {
        {" Open", -3.0}, {" Pick", -3.2}, {" Put", -3.4}, {" Close", -3.6}, {" Wash", -3.8}};
    if (static_cast<int>(alternatives.size()) > logprobs - 1) alternatives.resize(std::max(logprobs - 1, 0));
    return Answer{" " + word, {" " + word}, -0.1, alternatives, prompt_tokens, Answer::End::kLength};
  }
  // The rest of a step after its first word: the usual step if the word
  // fits it, with "the" when asked again at a higher temperature.
  std::string given = after_last(prompt, std::to_string(number) + ". ", "\n");
  std::vector<std::string> worded = usual_steps(prompt, temperature > 0 && asked > 0);
  std::string rest = " something";
  for (const std::string& s : worded)
    if (s.rfind(given + " ", 0) == 0) {
      rest = s.substr(given.size());
      break;
    }
  std::vector<std::string> tokens;
  for (const std::string& w : words_of(rest)) tokens.push_back(" " + w);
  return Answer{rest, tokens, -0.3, {}, prompt_tokens};
}

HungServer::HungServer() {
  fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (fd_ < 0 || ::bind(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 || ::listen(fd_, 64) != 0)
    throw std::runtime_error("cannot open a listening socket");
  socklen_t length = sizeof address;
  ::getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &length);
  port_ = ntohs(address.sin_port);
}

HungServer::~HungServer() { ::close(fd_); }

int closed_port() {
  int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address);
  socklen_t length = sizeof address;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
  ::close(fd);
  return ntohs(address.sin_port);
}

}  // namespace apprentice::testing
