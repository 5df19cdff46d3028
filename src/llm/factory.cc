#include "llm/factory.h"

#include <cstdlib>
#include <filesystem>

#include "llm/cassette.h"
#include "llm/corpus_client.h"
#include "llm/placement_corpus.h"
#include "llm/http_client.h"
#include "util/text.h"

namespace apprentice::llm {
namespace {

constexpr std::string_view kSpecForms =
    "expected openai:URL, openai, openai-chat:URL, llama:URL, replay:FILE, record:FILE,SPEC, corpus:FILE, "
    "corpus:FILE,condition=NAME or corpus:FILE,pool=all";

std::string env_or_empty(const char* name) {
  const char* value = std::getenv(name);
  return value == nullptr ? std::string() : std::string(value);
}

bool ends_with(std::string_view text, std::string_view suffix) {
  return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

std::string without_trailing_slashes(std::string_view url) {
  while (!url.empty() && url.back() == '/') url.remove_suffix(1);
  return std::string(url);
}

// Whether the URL has a path after the host ("http://h:1/v1" does).
bool has_path(std::string_view url) {
  size_t scheme = url.find("://");
  size_t host_start = scheme == std::string_view::npos ? 0 : scheme + 3;
  return url.find('/', host_start) != std::string_view::npos;
}

Result<std::unique_ptr<LlmClient>> make_http(WireFormat format, std::string url,
                                             const LlmOptions& options) {
  if (url.find("://") == std::string::npos) {
    return make_error(ErrorCode::kInvalidInput,
                      "LLM URL must start with http:// or https://: " + apprentice::quoted(url));
  }
  HttpOptions http;
  http.format = format;
  http.endpoint = format == WireFormat::kOpenAi       ? openai_endpoint(url)
                  : format == WireFormat::kOpenAiChat ? openai_chat_endpoint(url)
                                                      : llama_endpoint(url);
  http.model = options.model.empty() ? env_or_empty("OPENAI_MODEL") : options.model;
  http.api_key = options.api_key ? *options.api_key : env_or_empty("OPENAI_API_KEY");
  http.seed = options.seed;
  http.connect_timeout = options.connect_timeout;
  http.request_timeout = options.request_timeout;
  http.stall_timeout = options.stall_timeout;
  http.max_retries = options.max_retries;
  http.backoff_initial = options.backoff_initial;
  http.backoff_max = options.backoff_max;
  http.retry_after_cap = options.retry_after_cap;
  http.sleep = options.sleep;
  return std::unique_ptr<LlmClient>(std::make_unique<HttpLlmClient>(std::move(http)));
}

Result<std::unique_ptr<LlmClient>> make_corpus(std::string_view rest, const LlmOptions& options) {
  // FILE[,condition=NAME][,pool=all]: the options follow the last comma-free
  // file name, so a path may not itself hold ",condition=" or ",pool=".
  CorpusSelection selection;
  selection.condition = options.corpus_condition;
  std::string path(rest);
  bool named = false;
  for (std::string_view option : {std::string_view(",condition="), std::string_view(",pool=")}) {
    const size_t at = path.find(option);
    if (at == std::string::npos) continue;
    const size_t end = path.find(',', at + 1);
    const std::string value = path.substr(at + option.size(), end == std::string::npos ? end : end - at - option.size());
    if (option == ",pool=") {
      if (value != "all")
        return make_error(ErrorCode::kInvalidInput, "corpus: pool= takes only all (an ensemble of every condition), not " +
                                                        apprentice::quoted(value));
      if (named) return make_error(ErrorCode::kInvalidInput, "corpus: choose condition=NAME or pool=all, not both");
      selection.pool_all = true;
      selection.condition.clear();
    } else {
      selection.condition = value;
      named = true;
    }
    path.erase(at, end == std::string::npos ? std::string::npos : end - at);
  }
  if (path.empty()) return make_error(ErrorCode::kInvalidInput, "corpus: needs a file");
  // Recorded summaries and placements (the TidyBot benchmark's) rather than goal statements.
  if (PlacementCorpusClient::recognizes(path)) {
    if (named || selection.pool_all)
      return make_error(ErrorCode::kInvalidInput, "corpus: " + path + " holds summaries and placements, which have no "
                                                  "conditions to choose (no ,condition= or ,pool=)");
    auto placements = PlacementCorpusClient::open(path);
    if (!placements) return tl::unexpected(placements.error());
    return std::unique_ptr<LlmClient>(std::move(*placements));
  }
  auto client = CorpusClient::open(path, selection);
  if (!client) return tl::unexpected(client.error());
  return std::unique_ptr<LlmClient>(std::move(*client));
}

}  // namespace

std::string spec_for_condition(std::string_view spec, std::string_view condition) {
  auto renamed = [&](std::string_view file) {
    std::filesystem::path path{std::string(file)};
    return (path.parent_path() / (path.stem().string() + "." + std::string(condition) + path.extension().string()))
        .string();
  };
  spec = trim(spec);
  if (spec.rfind("replay:", 0) == 0) return "replay:" + renamed(spec.substr(7));
  if (spec.rfind("record:", 0) == 0) {
    std::string_view rest = spec.substr(7);
    const size_t comma = rest.find(',');
    if (comma == std::string_view::npos) return std::string(spec);  // malformed: make_llm_client says so
    return "record:" + renamed(rest.substr(0, comma)) + "," + spec_for_condition(rest.substr(comma + 1), condition);
  }
  return std::string(spec);
}

std::string openai_endpoint(std::string_view base_url) {
  std::string url = without_trailing_slashes(base_url);
  if (ends_with(url, "/completions")) return url;
  if (!has_path(url)) return url + "/v1/completions";
  return url + "/completions";
}

std::string openai_chat_endpoint(std::string_view base_url) {
  std::string url = without_trailing_slashes(base_url);
  if (ends_with(url, "/chat/completions")) return url;
  if (!has_path(url)) return url + "/v1/chat/completions";
  return url + "/chat/completions";
}

std::string llama_endpoint(std::string_view base_url) {
  std::string url = without_trailing_slashes(base_url);
  if (ends_with(url, "/completion")) return url;
  return url + "/completion";
}

Status check_llm_connection(std::string_view spec, const LlmOptions& options) {
  spec = trim(spec);
  if (spec.rfind("record:", 0) == 0) {
    const size_t comma = spec.find(',');
    if (comma == std::string_view::npos) {
      auto malformed = make_llm_client(spec, options);  // says what is wrong
      if (!malformed) return tl::unexpected(malformed.error());
      return {};
    }
    return check_llm_connection(spec.substr(comma + 1), options);
  }
  for (std::string_view scheme : {"openai", "openai-chat", "llama"}) {
    if (spec == scheme || spec.rfind(std::string(scheme) + ":", 0) == 0) {
      auto client = make_llm_client(spec, options);
      if (!client) return tl::unexpected(client.error());
      // These schemes always make an HttpLlmClient (make_http).
      return static_cast<HttpLlmClient&>(**client).check_connection();
    }
  }
  return {};
}

std::optional<std::string> resolve_llm_spec(std::string_view flag) {
  if (!flag.empty()) return std::string(flag);
  std::string env = env_or_empty("APPRENTICE_LLM");
  if (!env.empty()) return env;
  return std::nullopt;
}

Result<std::unique_ptr<LlmClient>> make_llm_client(std::string_view spec, const LlmOptions& options) {
  spec = trim(spec);
  const size_t colon = spec.find(':');
  const std::string_view scheme = spec.substr(0, colon);
  const std::string_view rest = colon == std::string_view::npos ? "" : spec.substr(colon + 1);
  if (scheme == "openai" || scheme == "openai-chat") {
    std::string url(rest.empty() ? env_or_empty("OPENAI_BASE_URL") : rest);
    if (url.empty()) {
      return make_error(ErrorCode::kInvalidInput, std::string(scheme) + ": needs a URL (" + std::string(scheme) +
                                                      ":http://host:port/v1) or OPENAI_BASE_URL");
    }
    return make_http(scheme == "openai" ? WireFormat::kOpenAi : WireFormat::kOpenAiChat, std::move(url), options);
  }
  if (scheme == "llama" && !rest.empty()) {
    return make_http(WireFormat::kLlamaNative, std::string(rest), options);
  }
  if (scheme == "replay" && !rest.empty()) {
    auto client = ReplayClient::open(std::string(rest));
    if (!client) return tl::unexpected(client.error());
    return std::unique_ptr<LlmClient>(std::move(*client));
  }
  if (scheme == "record") {
    const size_t comma = rest.find(',');
    if (comma == std::string_view::npos || comma == 0 || comma + 1 == rest.size()) {
      return make_error(ErrorCode::kInvalidInput, "record: needs FILE,SPEC, e.g. "
                                                  "record:run.jsonl,openai:http://127.0.0.1:8080/v1");
    }
    auto inner = make_llm_client(rest.substr(comma + 1), options);
    if (!inner) return tl::unexpected(inner.error());
    auto client = RecordingClient::open(std::string(rest.substr(0, comma)), std::move(*inner));
    if (!client) return tl::unexpected(client.error());
    return std::unique_ptr<LlmClient>(std::move(*client));
  }
  if (scheme == "corpus" && !rest.empty()) return make_corpus(rest, options);
  return make_error(ErrorCode::kInvalidInput,
                    "unknown LLM backend " + apprentice::quoted(spec) + ": " + std::string(kSpecForms));
}

}  // namespace apprentice::llm
