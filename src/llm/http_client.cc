#include "llm/http_client.h"

#include <curl/curl.h>

#include <algorithm>
#include <cctype>
#include <thread>

#include "util/check.h"
#include "util/log.h"
#include "util/text.h"

namespace apprentice::llm {
namespace {

// The largest response body we accept; completions are a few KiB.
constexpr size_t kMaxBodyBytes = 16 * 1024 * 1024;

// curl_global_init must run once before any other libcurl call and is not
// safe to race with other threads. A function-local static gives exactly
// that (C++ guarantees one thread-safe initialisation) without a global
// object. It is never undone: libcurl stays usable until the process exits.
void ensure_curl_initialised() {
  static const CURLcode init = curl_global_init(CURL_GLOBAL_DEFAULT);
  APPRENTICE_CHECK_MSG(init == CURLE_OK, "curl_global_init failed");
}

size_t on_body(char* data, size_t size, size_t count, void* user) {
  auto* body = static_cast<std::string*>(user);
  const size_t bytes = size * count;
  if (body->size() + bytes > kMaxBodyBytes) return 0;  // makes curl fail: too large
  body->append(data, bytes);
  return bytes;
}

// Reads "Retry-After: <seconds>" (the HTTP-date form is ignored: we then
// fall back to our own backoff).
size_t on_header(char* data, size_t size, size_t count, void* user) {
  auto* retry_after = static_cast<std::optional<std::chrono::milliseconds>*>(user);
  const size_t bytes = size * count;
  std::string_view line(data, bytes);
  constexpr std::string_view kName = "retry-after:";
  if (starts_with_ignoring_case(line, kName)) {
    std::string_view value = trim(line.substr(kName.size()));
    if (!value.empty() && value.size() < 9 &&
        std::all_of(value.begin(), value.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
      *retry_after = std::chrono::seconds(std::stol(std::string(value)));
    }
  }
  return bytes;
}

// "http://user:secret@host/x" -> "http://[redacted]@host/x".
std::string without_userinfo(std::string_view url) {
  size_t scheme = url.find("://");
  if (scheme == std::string_view::npos) return std::string(url);
  size_t host_start = scheme + 3;
  size_t path = url.find('/', host_start);
  size_t at = url.find('@', host_start);
  if (at == std::string_view::npos || (path != std::string_view::npos && at > path)) {
    return std::string(url);
  }
  return std::string(url.substr(0, host_start)) + "[redacted]" + std::string(url.substr(at));
}

bool is_retryable_transport(CURLcode code) {
  switch (code) {
    case CURLE_COULDNT_CONNECT:
    case CURLE_GOT_NOTHING:
    case CURLE_RECV_ERROR:
    case CURLE_SEND_ERROR:
    case CURLE_PARTIAL_FILE:
      return true;
    default:
      return false;
  }
}

}  // namespace

struct HttpLlmClient::Handle {
  CURL* curl = nullptr;
  ~Handle() {
    if (curl != nullptr) curl_easy_cleanup(curl);
  }
};

struct HttpLlmClient::Attempt {
  CURLcode code = CURLE_OK;
  long status = 0;
  std::string body;
  std::optional<std::chrono::milliseconds> retry_after;
  std::string curl_message;  // libcurl's own explanation when code != OK
  bool connected = false;    // the connection was made (a timeout came later)
};

HttpLlmClient::HttpLlmClient(HttpOptions options)
    : options_(std::move(options)), handle_(std::make_unique<Handle>()) {
  APPRENTICE_CHECK(options_.transport.max_retries >= 0);
  ensure_curl_initialised();
  handle_->curl = curl_easy_init();
  APPRENTICE_CHECK_MSG(handle_->curl != nullptr, "curl_easy_init failed");
}

HttpLlmClient::~HttpLlmClient() = default;

std::string HttpLlmClient::describe() const {
  std::string out = options_.format == WireFormat::kOpenAi       ? "openai "
                    : options_.format == WireFormat::kOpenAiChat ? "openai-chat "
                                                                 : "llama ";
  out += without_userinfo(options_.endpoint);
  if (!options_.wire.model.empty()) out += " model=" + options_.wire.model;
  return out;
}

Error HttpLlmClient::scrub(Error error) const {
  const std::string& key = options_.api_key;
  if (key.empty()) return error;
  size_t pos = 0;
  while ((pos = error.message.find(key, pos)) != std::string::npos) {
    error.message.replace(pos, key.size(), "[redacted]");
    pos += 10;
  }
  return error;
}

HttpLlmClient::Attempt HttpLlmClient::post_once(const std::string& body) {
  Attempt attempt;
  CURL* curl = handle_->curl;
  curl_easy_reset(curl);  // keeps the connection cache, drops old options
  char error_buffer[CURL_ERROR_SIZE] = {0};
  curl_slist* headers = nullptr;
  headers = curl_slist_append(headers, "Content-Type: application/json");
  headers = curl_slist_append(headers, "Accept: application/json");
  std::string authorization;
  if (!options_.api_key.empty()) {
    authorization = "Authorization: Bearer " + options_.api_key;
    headers = curl_slist_append(headers, authorization.c_str());
  }
  curl_easy_setopt(curl, CURLOPT_URL, options_.endpoint.c_str());
  curl_easy_setopt(curl, CURLOPT_POST, 1L);
  curl_easy_setopt(curl, CURLOPT_POSTFIELDS, body.data());
  curl_easy_setopt(curl, CURLOPT_POSTFIELDSIZE_LARGE, static_cast<curl_off_t>(body.size()));
  curl_easy_setopt(curl, CURLOPT_HTTPHEADER, headers);
  curl_easy_setopt(curl, CURLOPT_USERAGENT, "apprentice");
  curl_easy_setopt(curl, CURLOPT_NOSIGNAL, 1L);  // timeouts without SIGALRM
  // The one deadline of an attempt is request_timeout, the connection's
  // within it (HttpTransport).
  curl_easy_setopt(curl, CURLOPT_CONNECTTIMEOUT_MS, static_cast<long>(options_.transport.connect_timeout.count()));
  curl_easy_setopt(curl, CURLOPT_TIMEOUT_MS, static_cast<long>(options_.transport.request_timeout.count()));
  curl_easy_setopt(curl, CURLOPT_WRITEFUNCTION, on_body);
  curl_easy_setopt(curl, CURLOPT_WRITEDATA, &attempt.body);
  curl_easy_setopt(curl, CURLOPT_HEADERFUNCTION, on_header);
  curl_easy_setopt(curl, CURLOPT_HEADERDATA, &attempt.retry_after);
  curl_easy_setopt(curl, CURLOPT_ERRORBUFFER, error_buffer);

  attempt.code = curl_easy_perform(curl);
  curl_easy_getinfo(curl, CURLINFO_RESPONSE_CODE, &attempt.status);
  // Connected: a new connection was made, or the request went out on one
  // kept from an earlier answer (curl gives a reused connection no connect
  // time, so that alone blamed connecting for a server that hung after it).
  curl_off_t connect_time = 0;
  long request_size = 0;
  curl_easy_getinfo(curl, CURLINFO_CONNECT_TIME_T, &connect_time);
  curl_easy_getinfo(curl, CURLINFO_REQUEST_SIZE, &request_size);
  attempt.connected = connect_time > 0 || request_size > 0;
  if (attempt.code != CURLE_OK) {
    attempt.curl_message = error_buffer[0] != '\0' ? std::string(error_buffer)
                                                   : std::string(curl_easy_strerror(attempt.code));
    if (attempt.code == CURLE_WRITE_ERROR) attempt.curl_message = "response body larger than 16 MiB";
  }
  // The handle must not keep pointers into this frame.
  curl_easy_setopt(curl, CURLOPT_HTTPHEADER, nullptr);
  curl_easy_setopt(curl, CURLOPT_ERRORBUFFER, nullptr);
  curl_slist_free_all(headers);
  return attempt;
}

namespace {

// Whether a refusal's body says the model is unknown or missing (vLLM: "The
// model `x` does not exist.", Ollama: "model \"x\" not found, try pulling
// it first", OpenAI: "model_not_found"), rather than, say, that the prompt
// is longer than the model's context.
bool refuses_the_model(std::string_view body) {
  const std::string text = to_lower(body);
  if (text.find("model") == std::string::npos) return false;
  for (std::string_view says : {"not found", "does not exist", "not exist", "unknown model", "no such model",
                                "model_not_found", "must provide", "model is required", "invalid model"})
    if (text.find(says) != std::string::npos) return true;
  return false;
}

}  // namespace

// A refusal (4xx other than 429) as the configuration error it is, naming
// the flag to fix, in one line.
Error HttpLlmClient::refusal(long status, std::string_view body) const {
  const std::string where = without_userinfo(options_.endpoint);
  const std::string answered = "HTTP " + std::to_string(status) + ": " + excerpt_for_message(body);
  if (status == 401 || status == 403)
    return Error{ErrorCode::kFailedPrecondition, "the LLM server at " + where + " refused the API key (" + answered +
                                                     "); fix --llm-api-key or OPENAI_API_KEY"};
  if (refuses_the_model(body)) {
    const std::string model = options_.wire.model.empty() ? std::string("no model was sent")
                                                          : "the model sent was " + apprentice::quoted(options_.wire.model);
    return Error{status == 404 ? ErrorCode::kNotFound : ErrorCode::kInvalidInput,
                 "the LLM server at " + where + " does not serve the model asked for (" +
                                               answered + "; " + model + "); fix --llm-model or OPENAI_MODEL"};
  }
  if (status == 404)
    return Error{ErrorCode::kNotFound,
                 "the LLM server at " + where + " has no such endpoint (" + answered +
                     "); fix the URL in --llm: openai: and openai-chat: take the API base (http://host:port/v1), "
                     "llama: the server root (http://host:port)"};
  return Error{ErrorCode::kInvalidInput,
               "the LLM server at " + where + " refused the request (" + answered + "); check --llm and --llm-model"};
}

Result<Completion> HttpLlmClient::do_complete(const CompletionRequest& request) {
  const std::string body = build_request_body(options_.format, request, options_.wire);
  const std::string where = without_userinfo(options_.endpoint);
  const HttpTransport& transport = options_.transport;
  const int attempts = transport.max_retries + 1;
  Error last{ErrorCode::kUnavailable, "no attempt made"};
  for (int n = 0; n < attempts; ++n) {
    Attempt attempt = post_once(body);
    std::chrono::milliseconds wait = std::min<std::chrono::milliseconds>(
        transport.backoff_max, transport.backoff_initial * (int64_t{1} << std::min(n, 20)));
    if (attempt.code == CURLE_OPERATION_TIMEDOUT) {
      // Not retried: asking a server that is too slow again doubles the wait.
      const std::string bound =
          attempt.connected ? "no answer within " + std::to_string(transport.request_timeout.count()) +
                                  " ms (--llm-timeout-ms)"
                            : "no connection within " +
                                  std::to_string(std::min(transport.connect_timeout, transport.request_timeout).count()) +
                                  " ms (--llm-connect-timeout-ms)";
      return tl::unexpected(scrub(Error{ErrorCode::kDeadlineExceeded,
                                        "no answer from the LLM server at " + where + " in time: " + bound}));
    }
    if (attempt.code != CURLE_OK) {
      last = Error{ErrorCode::kUnavailable,
                   "cannot get an answer from the LLM server at " + where + ": " + attempt.curl_message};
      if (!is_retryable_transport(attempt.code)) return tl::unexpected(scrub(std::move(last)));
    } else if (attempt.status >= 200 && attempt.status < 300) {
      Result<Completion> parsed = parse_response_body(options_.format, attempt.body);
      if (!parsed) return tl::unexpected(scrub(prefix_error(parsed.error(), where)));
      return parsed;
    } else if (attempt.status == 429 || attempt.status >= 500) {
      last = Error{ErrorCode::kUnavailable, "the LLM server at " + where + " answered HTTP " +
                                                std::to_string(attempt.status) + ": " +
                                                excerpt_for_message(attempt.body)};
      if (attempt.retry_after) wait = std::min(*attempt.retry_after, transport.retry_after_cap);
    } else {
      return tl::unexpected(scrub(refusal(attempt.status, attempt.body)));
    }
    if (n + 1 < attempts) {
      spdlog::info("{}; retrying in {} ms (attempt {} of {})", scrub(last).message, wait.count(),
                   n + 2, attempts);
      if (transport.sleep) {
        transport.sleep(wait);
      } else {
        std::this_thread::sleep_for(wait);
      }
    }
  }
  last.message += " (gave up after " + std::to_string(attempts) + " attempts)";
  return tl::unexpected(scrub(std::move(last)));
}

}  // namespace apprentice::llm
