// Protocol and fault tests of the HTTP backends against servers running in
// this process on 127.0.0.1.
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>

#include "llm/chat_shapes.h"
#include "llm/factory.h"
#include "llm/http_client.h"
#include "llm/test_server.h"

namespace apprentice::llm {
namespace {

using nlohmann::json;
using std::chrono::milliseconds;
using testing::RawTcpServer;
using testing::TestHttpServer;

constexpr const char* kKey = "sk-secret-0123456789";

const char* const kOpenAiBody = R"({"id":"cmpl-1","object":"text_completion","created":1,
  "choices":[{"text":" The goal is that the ceramic-plate is in the cupboard","index":0,
  "finish_reason":"stop","logprobs":{"tokens":[" The"," goal"],"token_logprobs":[-0.05,-0.01],
  "top_logprobs":[{" The":-0.05," the":-3.1},{" goal":-0.01}]}}],
  "usage":{"prompt_tokens":250,"completion_tokens":12,"total_tokens":262}})";

const char* const kNativeBody = R"({"content":" Open","stop":true,"stop_type":"limit",
  "tokens_predicted":1,"tokens_evaluated":301,"completion_probabilities":[{"id":1,"token":" Open",
  "logprob":-0.6,"top_logprobs":[{"id":1,"token":" Open","logprob":-0.6},
  {"id":2,"token":" Pick","logprob":-1.58},{"id":3,"token":" Check","logprob":-2.7}]}]})";

LlmOptions fast_options() {
  LlmOptions options;
  options.api_key = kKey;
  options.model = "test-model";
  options.transport.connect_timeout = milliseconds(1000);
  options.transport.request_timeout = milliseconds(3000);
  options.transport.max_retries = 2;
  options.transport.backoff_initial = milliseconds(10);
  options.transport.backoff_max = milliseconds(20);
  options.transport.retry_after_cap = milliseconds(2000);
  return options;
}

std::unique_ptr<LlmClient> openai_client(const std::string& base, const LlmOptions& options) {
  auto client = make_llm_client("openai:" + base + "/v1", options);
  EXPECT_TRUE(client.has_value()) << client.error().describe();
  return std::move(*client);
}

CompletionRequest goal_request() {
  CompletionRequest request;
  request.prompt = "(TASK) Task name: tidy kitchen.\n(RESULT)";
  request.temperature = 0.0;
  request.max_tokens = 64;
  request.stop = {"(END RESULT)"};
  return request;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The waits between attempts, recorded instead of slept, so that the tests
// check them exactly without a wall clock (a loaded machine never makes
// them flaky).
struct Waits {
  std::shared_ptr<std::vector<milliseconds>> taken = std::make_shared<std::vector<milliseconds>>();
  LlmOptions inject(LlmOptions options) const {
    options.transport.sleep = [taken = taken](milliseconds wait) { taken->push_back(wait); };
    return options;
  }
  std::vector<milliseconds> operator()() const { return *taken; }
};

// Timeouts are curl's own, on the wall clock. Their tests check the error
// and only that the call ended well before the server would have answered:
// a bound this loose cannot fail on a slow machine, yet catches a timeout
// that does not fire.
constexpr double kLongBeforeTheServerAnswers = 20.0;

int unused_port() {
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

void expect_no_key(const Error& error) {
  EXPECT_EQ(error.message.find(kKey), std::string::npos) << error.message;
}

TEST(HttpClientTest, OpenAiProtocol) {
  TestHttpServer server;
  json seen;
  std::string authorization;
  server.server().Post("/v1/completions", [&](const httplib::Request& req, httplib::Response& res) {
    seen = json::parse(req.body);
    authorization = req.get_header_value("Authorization");
    res.set_content(kOpenAiBody, "application/json");
  });
  server.start();
  auto client = openai_client(server.url(), fast_options());
  auto completion = client->complete(goal_request());
  ASSERT_TRUE(completion.has_value()) << completion.error().describe();
  EXPECT_EQ(completion->text, " The goal is that the ceramic-plate is in the cupboard");
  EXPECT_EQ(completion->tokens.size(), 2u);
  EXPECT_EQ(completion->top_logprobs[0][0], (TokenLogprob{" The", -0.05}));
  EXPECT_EQ(completion->completion_tokens, 12);
  EXPECT_EQ(seen["model"], "test-model");
  EXPECT_EQ(seen["prompt"], goal_request().prompt);
  EXPECT_EQ(seen["logprobs"], 1);
  EXPECT_EQ(seen["stop"], json::array({"(END RESULT)"}));
  EXPECT_EQ(authorization, std::string("Bearer ") + kKey);
  EXPECT_EQ(client->usage().prompt_tokens, 250);
  EXPECT_EQ(client->usage().completion_tokens, 12);
  EXPECT_EQ(client->describe().find(kKey), std::string::npos);
}

// Issue 13, item 5: openai-chat:URL against the fake server answering in
// each server's chat reply shape.
class ChatServerTest : public ::testing::TestWithParam<testing::ChatShape> {};

TEST_P(ChatServerTest, TheChatBackendReadsTheReplyAndAsksForTheAlternatives) {
  TestHttpServer server;
  std::vector<json> requests;
  std::mutex mutex;
  server.server().Post("/v1/chat/completions", [&](const httplib::Request& req, httplib::Response& res) {
    {
      std::lock_guard lock(mutex);
      requests.push_back(json::parse(req.body));
    }
    res.set_content(GetParam().body, "application/json");
  });
  server.start();
  auto client = make_llm_client("openai-chat:" + server.url() + "/v1", fast_options());
  ASSERT_TRUE(client.has_value()) << client.error().describe();
  EXPECT_NE((*client)->describe().find("openai-chat " + server.url() + "/v1/chat/completions"), std::string::npos);
  auto completion = (*client)->complete(goal_request());
  ASSERT_TRUE(completion.has_value()) << completion.error().describe();
  EXPECT_EQ(completion->text, " Open dishwasher");
  EXPECT_NEAR(std::exp(*mean_logprob(completion->tokens)), std::exp((-0.02 - 0.3 - 0.001) / 3), 1e-12);
  auto words = next_token_alternatives(**client, "Steps:\n1.", 5, QueryAbout{});
  ASSERT_TRUE(words.has_value()) << words.error().describe();
  ASSERT_GE(words->size(), 2u);
  EXPECT_EQ((*words)[0].token, " Open");
  EXPECT_EQ((*words)[1].token, " Pick");
  ASSERT_EQ(requests.size(), 2u);
  EXPECT_EQ(requests[0]["messages"][0]["content"], goal_request().prompt);
  EXPECT_EQ(requests[0]["logprobs"], true);
  EXPECT_EQ(requests[1]["messages"][0]["content"], "Steps:\n1.");
  EXPECT_EQ(requests[1]["top_logprobs"], 5);
  EXPECT_EQ(requests[1]["max_tokens"], 1);
}

INSTANTIATE_TEST_SUITE_P(Servers, ChatServerTest, ::testing::ValuesIn(testing::chat_shapes()),
                         [](const auto& info) {
                           std::string name = info.param.server;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

TEST(HttpClientTest, AChatServerWithoutLogprobsStillGivesTheChosenWord) {
  TestHttpServer server;
  server.server().Post("/v1/chat/completions", [&](const httplib::Request&, httplib::Response& res) {
    res.set_content(testing::kChatWithoutLogprobs, "application/json");
  });
  server.start();
  auto client = make_llm_client("openai-chat:" + server.url(), fast_options());
  ASSERT_TRUE(client.has_value()) << client.error().describe();
  auto words = next_token_alternatives(**client, "Steps:\n1.", 5, QueryAbout{});
  ASSERT_TRUE(words.has_value()) << words.error().describe();
  ASSERT_EQ(words->size(), 1u);
  EXPECT_EQ((*words)[0].token, " Open");
  EXPECT_TRUE(std::isnan((*words)[0].logprob));
}

// Issue 13, item 6, and issue 25, item 6: whether the server answers,
// before a run depends on it, by one real one-token request (a socket that
// only accepts would pass a connection check), never recorded.
TEST(HttpClientTest, TheServerCheckSendsOneTinyRequestAndSaysWhyItFails) {
  TestHttpServer server;
  std::atomic<int> hits{0};
  json seen;
  server.server().Post("/v1/completions", [&](const httplib::Request& req, httplib::Response& res) {
    ++hits;
    seen = json::parse(req.body);
    res.set_content(kOpenAiBody, "application/json");
  });
  server.start();
  auto checked = check_llm_server("openai:" + server.url() + "/v1", fast_options());
  ASSERT_TRUE(checked.has_value()) << checked.error().describe();
  EXPECT_TRUE(checked->asked);
  EXPECT_EQ(checked->logprobs, LogprobsArrived::kYes);
  EXPECT_EQ(hits.load(), 1);
  EXPECT_EQ(seen["max_tokens"], 1);
  EXPECT_EQ(seen["prompt"], "Hello");
  EXPECT_TRUE(check_llm_server("record:/nonexistent/dir/x.jsonl,openai:" + server.url(), fast_options()).has_value());
  EXPECT_EQ(hits.load(), 2);
  EXPECT_FALSE(std::filesystem::exists("/nonexistent/dir/x.jsonl"));
  const std::string dead = "http://127.0.0.1:" + std::to_string(unused_port());
  LlmOptions once = fast_options();
  once.transport.max_retries = 0;
  for (const std::string& spec : {"openai:" + dead, "openai-chat:" + dead, "llama:" + dead, "record:x.jsonl,openai:" + dead}) {
    SCOPED_TRACE(spec);
    auto refused = check_llm_server(spec, once);
    ASSERT_FALSE(refused.has_value());
    EXPECT_EQ(refused.error().code, ErrorCode::kUnavailable);
    EXPECT_NE(refused.error().message.find("cannot get an answer from the LLM server at " + dead), std::string::npos)
        << refused.error().message;
  }
  // A listener that accepts and never answers: the check waits out the request timeout.
  RawTcpServer hung(RawTcpServer::Mode::kHang);
  LlmOptions quick = fast_options();
  quick.transport.request_timeout = milliseconds(300);
  auto silent = check_llm_server("openai:" + hung.url() + "/v1", quick);
  ASSERT_FALSE(silent.has_value());
  EXPECT_EQ(silent.error().code, ErrorCode::kDeadlineExceeded);
  EXPECT_NE(silent.error().message.find("no answer within 300 ms (--llm-timeout-ms)"), std::string::npos)
      << silent.error().message;
  auto corpus = check_llm_server("corpus:whatever.jsonl", fast_options());  // no server to reach
  ASSERT_TRUE(corpus.has_value());
  EXPECT_FALSE(corpus->asked);
  EXPECT_EQ(check_llm_server("bogus:x", fast_options()).error().code, ErrorCode::kInvalidInput);
}

TEST(HttpClientTest, LlamaNativeProtocolAndNextTokenQuery) {
  TestHttpServer server;
  json seen;
  server.server().Post("/completion", [&](const httplib::Request& req, httplib::Response& res) {
    seen = json::parse(req.body);
    res.set_content(kNativeBody, "application/json");
  });
  server.start();
  auto client = make_llm_client("llama:" + server.url(), fast_options());
  ASSERT_TRUE(client.has_value()) << client.error().describe();
  QueryAbout about;
  about.kind = QueryKind::kActionWord;
  auto words = next_token_alternatives(**client, "Steps:\n1.", 5, about);
  ASSERT_TRUE(words.has_value()) << words.error().describe();
  ASSERT_EQ(words->size(), 3u);
  EXPECT_EQ((*words)[0], (TokenLogprob{" Open", -0.6}));
  EXPECT_EQ((*words)[1].token, " Pick");
  EXPECT_EQ(seen["n_predict"], 1);
  EXPECT_EQ(seen["n_probs"], 5);
  EXPECT_EQ(seen["temperature"], 0.0);
}

TEST(HttpClientTest, RetriesA500ThenSucceeds) {
  TestHttpServer server;
  std::atomic<int> hits{0};
  server.server().Post("/v1/completions", [&](const httplib::Request&, httplib::Response& res) {
    if (hits++ == 0) {
      res.status = 500;
      res.set_content("internal error", "text/plain");
      return;
    }
    res.set_content(kOpenAiBody, "application/json");
  });
  server.start();
  auto client = openai_client(server.url(), fast_options());
  auto completion = client->complete(goal_request());
  ASSERT_TRUE(completion.has_value()) << completion.error().describe();
  EXPECT_EQ(hits.load(), 2);
}

TEST(HttpClientTest, GivesUpAfterTheLastRetry) {
  TestHttpServer server;
  std::atomic<int> hits{0};
  server.server().Post("/v1/completions", [&](const httplib::Request&, httplib::Response& res) {
    ++hits;
    res.status = 503;
    res.set_content("{\"error\":\"loading model\"}", "application/json");
  });
  server.start();
  Waits waits;
  auto client = openai_client(server.url(), waits.inject(fast_options()));
  auto completion = client->complete(goal_request());
  ASSERT_FALSE(completion.has_value());
  EXPECT_EQ(completion.error().code, ErrorCode::kUnavailable);
  EXPECT_NE(completion.error().message.find("HTTP 503"), std::string::npos) << completion.error().message;
  EXPECT_NE(completion.error().message.find("loading model"), std::string::npos);
  EXPECT_NE(completion.error().message.find("gave up after 3 attempts"), std::string::npos);
  EXPECT_EQ(hits.load(), 3);
  // Backoff 10 ms, then doubled, capped at 20 ms; none after the last attempt.
  EXPECT_EQ(waits(), (std::vector<milliseconds>{milliseconds(10), milliseconds(20)}));
  EXPECT_EQ(client->usage().failures, 1);
}

TEST(HttpClientTest, HonoursRetryAfterOn429) {
  TestHttpServer server;
  std::atomic<int> hits{0};
  server.server().Post("/v1/completions", [&](const httplib::Request&, httplib::Response& res) {
    if (hits++ == 0) {
      res.status = 429;
      res.set_header("Retry-After", "1");
      res.set_content("{\"error\":{\"message\":\"rate limited\"}}", "application/json");
      return;
    }
    res.set_content(kOpenAiBody, "application/json");
  });
  server.start();
  Waits waits;
  auto client = openai_client(server.url(), waits.inject(fast_options()));
  auto completion = client->complete(goal_request());
  ASSERT_TRUE(completion.has_value()) << completion.error().describe();
  // Waited as told, not the 10 ms backoff.
  EXPECT_EQ(waits(), (std::vector<milliseconds>{milliseconds(1000)}));
  EXPECT_EQ(hits.load(), 2);
}

TEST(HttpClientTest, RetryAfterIsCapped) {
  TestHttpServer server;
  std::atomic<int> hits{0};
  server.server().Post("/v1/completions", [&](const httplib::Request&, httplib::Response& res) {
    ++hits;
    res.status = 429;
    res.set_header("Retry-After", "3600");
    res.set_content("slow down", "text/plain");
  });
  server.start();
  Waits waits;
  LlmOptions options = waits.inject(fast_options());
  options.transport.retry_after_cap = milliseconds(50);
  auto client = openai_client(server.url(), options);
  auto completion = client->complete(goal_request());
  ASSERT_FALSE(completion.has_value());
  EXPECT_NE(completion.error().message.find("HTTP 429"), std::string::npos);
  EXPECT_EQ(waits(), (std::vector<milliseconds>{milliseconds(50), milliseconds(50)}));  // not an hour
  EXPECT_EQ(hits.load(), 3);
}

TEST(HttpClientTest, SlowServerTimesOutWithoutRetry) {
  TestHttpServer server;
  std::atomic<int> hits{0};
  server.server().Post("/v1/completions", [&](const httplib::Request&, httplib::Response& res) {
    ++hits;
    server.wait(milliseconds(60'000));  // returns early when the test ends
    res.set_content(kOpenAiBody, "application/json");
  });
  server.start();
  LlmOptions options = fast_options();
  options.transport.request_timeout = milliseconds(300);
  auto client = openai_client(server.url(), options);
  const auto start = std::chrono::steady_clock::now();
  auto completion = client->complete(goal_request());
  ASSERT_FALSE(completion.has_value());
  EXPECT_EQ(completion.error().code, ErrorCode::kDeadlineExceeded);
  EXPECT_NE(completion.error().message.find("in time"), std::string::npos) << completion.error().message;
  EXPECT_LT(seconds_since(start), kLongBeforeTheServerAnswers);
  EXPECT_EQ(hits.load(), 1);
}

struct BadBodyCase {
  const char* name;
  std::string body;
  const char* says;
};

class BadBodyTest : public ::testing::TestWithParam<BadBodyCase> {};

TEST_P(BadBodyTest, IsAClearErrorAndNotRetried) {
  TestHttpServer server;
  std::atomic<int> hits{0};
  server.server().Post("/v1/completions", [&](const httplib::Request&, httplib::Response& res) {
    ++hits;
    res.set_content(GetParam().body, "application/json");
  });
  server.start();
  auto client = openai_client(server.url(), fast_options());
  auto completion = client->complete(goal_request());
  ASSERT_FALSE(completion.has_value());
  EXPECT_EQ(completion.error().code, ErrorCode::kUnavailable);
  EXPECT_NE(completion.error().message.find(GetParam().says), std::string::npos)
      << completion.error().message;
  EXPECT_NE(completion.error().message.find(server.url()), std::string::npos);
  EXPECT_EQ(hits.load(), 1);
}

INSTANTIATE_TEST_SUITE_P(
    Faults, BadBodyTest,
    ::testing::Values(BadBodyCase{"truncated", std::string(kOpenAiBody).substr(0, 60), "cut short"},
                      BadBodyCase{"malformed", "{\"choices\": [oops]}", "not JSON"},
                      BadBodyCase{"invalid_utf8",
                                  "{\"choices\":[{\"text\":\" caf\xC3\x28 table\"}]}",
                                  "not valid UTF-8"},
                      BadBodyCase{"wrong_layout", "{\"content\":\"x\"}", "OpenAI completions layout"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(HttpClientTest, HungConnectionIsBoundedByTheRequestTimeout) {
  RawTcpServer server(RawTcpServer::Mode::kHang);
  LlmOptions options = fast_options();
  options.transport.request_timeout = milliseconds(700);
  auto client = openai_client(server.url(), options);
  const auto start = std::chrono::steady_clock::now();
  auto completion = client->complete(goal_request());
  ASSERT_FALSE(completion.has_value());
  EXPECT_EQ(completion.error().code, ErrorCode::kDeadlineExceeded);
  EXPECT_NE(completion.error().message.find("in time"), std::string::npos) << completion.error().message;
  EXPECT_LT(seconds_since(start), kLongBeforeTheServerAnswers);  // the server never answers
  EXPECT_EQ(server.connections(), 1);
}

// Issue 25, item 2: a fixed 30 s stall watch cut off a non-streaming server
// that sends nothing until it is done, whatever --llm-timeout-ms said. The
// request timeout is now the one deadline: a server silent for longer than
// any other limit but within it is answered.
TEST(HttpClientTest, ASilentServerGetsTheWholeRequestTimeout) {
  TestHttpServer server;
  server.server().Post("/v1/completions", [&](const httplib::Request&, httplib::Response& res) {
    server.wait(milliseconds(1500));  // nothing sent meanwhile
    res.set_content(kOpenAiBody, "application/json");
  });
  server.start();
  LlmOptions options = fast_options();
  options.transport.connect_timeout = milliseconds(1000);  // less than the silence: it bounds connecting only
  options.transport.request_timeout = milliseconds(10'000);
  auto client = openai_client(server.url(), options);
  auto completion = client->complete(goal_request());
  ASSERT_TRUE(completion.has_value()) << completion.error().describe();
  EXPECT_EQ(completion->tokens.size(), 2u);
  // And a shorter request timeout gives it up, naming the flag.
  options.transport.request_timeout = milliseconds(500);
  auto impatient = openai_client(server.url(), options);
  auto given_up = impatient->complete(goal_request());
  ASSERT_FALSE(given_up.has_value());
  EXPECT_EQ(given_up.error().code, ErrorCode::kDeadlineExceeded);
  EXPECT_NE(given_up.error().message.find("no answer within 500 ms (--llm-timeout-ms)"), std::string::npos)
      << given_up.error().message;
}

TEST(HttpClientTest, TransferCutShortIsRetriedThenReported) {
  RawTcpServer server(RawTcpServer::Mode::kCutBody);
  LlmOptions options = fast_options();
  options.transport.max_retries = 1;
  auto client = openai_client(server.url(), options);
  auto completion = client->complete(goal_request());
  ASSERT_FALSE(completion.has_value());
  EXPECT_EQ(completion.error().code, ErrorCode::kUnavailable);
  EXPECT_NE(completion.error().message.find("gave up after 2 attempts"), std::string::npos)
      << completion.error().message;
  EXPECT_EQ(server.connections(), 2);
}


TEST(HttpClientTest, RefusedConnectionIsRetriedThenReported) {
  Waits waits;
  auto client = openai_client("http://127.0.0.1:" + std::to_string(unused_port()), waits.inject(fast_options()));
  auto completion = client->complete(goal_request());
  ASSERT_FALSE(completion.has_value());
  EXPECT_EQ(completion.error().code, ErrorCode::kUnavailable);
  EXPECT_NE(completion.error().message.find("cannot get an answer"), std::string::npos);
  EXPECT_NE(completion.error().message.find("gave up after 3 attempts"), std::string::npos);
  EXPECT_EQ(waits(), (std::vector<milliseconds>{milliseconds(10), milliseconds(20)}));
}

TEST(HttpClientTest, ClientErrorsAreNotRetriedAndNeverShowTheKey) {
  TestHttpServer server;
  std::atomic<int> hits{0};
  server.server().Post("/v1/completions", [&](const httplib::Request& req, httplib::Response& res) {
    ++hits;
    const std::string model = json::parse(req.body).value("model", "");
    if (model == "missing") {
      res.status = 404;
      res.set_content("{\"error\":{\"message\":\"model not found\"}}", "application/json");
    } else if (model == "bad") {
      res.status = 400;
      res.set_content("{\"error\":{\"message\":\"max_tokens too large\"}}", "application/json");
    } else {
      res.status = 401;
      // Servers do echo keys back; we must not pass them on.
      res.set_content(std::string("{\"error\":{\"message\":\"Incorrect API key provided: ") + kKey + "\"}}",
                      "application/json");
    }
  });
  server.start();
  LlmOptions options = fast_options();
  auto unauthorised = openai_client(server.url(), options)->complete(goal_request());
  ASSERT_FALSE(unauthorised.has_value());
  EXPECT_EQ(unauthorised.error().code, ErrorCode::kFailedPrecondition);
  EXPECT_NE(unauthorised.error().message.find("[redacted]"), std::string::npos);
  EXPECT_NE(unauthorised.error().message.find("OPENAI_API_KEY"), std::string::npos);
  expect_no_key(unauthorised.error());
  options.model = "missing";
  auto missing = openai_client(server.url(), options)->complete(goal_request());
  ASSERT_FALSE(missing.has_value());
  EXPECT_EQ(missing.error().code, ErrorCode::kNotFound);
  EXPECT_NE(missing.error().message.find("fix --llm-model or OPENAI_MODEL"), std::string::npos) << missing.error().message;
  options.model = "bad";
  auto bad = openai_client(server.url(), options)->complete(goal_request());
  ASSERT_FALSE(bad.has_value());
  EXPECT_EQ(bad.error().code, ErrorCode::kInvalidInput);
  EXPECT_NE(bad.error().message.find("max_tokens too large"), std::string::npos);
  EXPECT_EQ(hits.load(), 3);
}

TEST(HttpClientTest, LogsNeverShowTheKey) {
  TestHttpServer server;
  std::atomic<int> hits{0};
  server.server().Post("/v1/completions", [&](const httplib::Request&, httplib::Response& res) {
    ++hits;
    res.status = 500;
    res.set_content(std::string("key ") + kKey + " is over quota", "text/plain");
  });
  server.start();
  std::ostringstream log;
  auto previous = spdlog::default_logger();
  auto capture = std::make_shared<spdlog::logger>(
      "capture", std::make_shared<spdlog::sinks::ostream_sink_mt>(log));
  capture->set_level(spdlog::level::trace);
  spdlog::set_default_logger(capture);
  auto completion = openai_client(server.url(), fast_options())->complete(goal_request());
  spdlog::set_default_logger(previous);
  ASSERT_FALSE(completion.has_value());
  expect_no_key(completion.error());
  EXPECT_NE(log.str().find("retrying"), std::string::npos) << log.str();
  EXPECT_EQ(log.str().find(kKey), std::string::npos) << log.str();
}

}  // namespace
}  // namespace apprentice::llm
