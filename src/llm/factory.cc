#include "llm/factory.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "llm/cassette.h"
#include "llm/corpus_client.h"
#include "llm/placement_corpus.h"
#include "llm/http_client.h"
#include "util/text.h"

namespace apprentice::llm {
namespace {

// The backends, once: their schemes and the forms they take. make_llm_client,
// check_llm_spec, the CLI's --llm help and every message listing the forms
// read this table.
struct Backend {
  std::string_view scheme;
  std::string_view forms;
  std::string_view options;  // what may follow, for --help
};
constexpr Backend kBackends[] = {
    {"openai", "openai:URL, openai", ""},
    {"openai-chat", "openai-chat:URL, openai-chat", ""},
    {"llama", "llama:URL", ""},
    {"replay", "replay:FILE", ""},
    {"record", "record:FILE,SPEC", ""},
    {"corpus", "corpus:FILE", "[,condition=NAME|,pool=all]"},
};

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

// A spec, read but not acted on: what check_llm_spec checks and
// make_llm_client builds from, so that the two read specs one way.
struct ParsedSpec {
  enum class Kind { kHttp, kReplay, kRecord, kCorpus } kind = Kind::kHttp;
  WireFormat format = WireFormat::kOpenAi;  // kHttp
  std::string target;                       // kHttp: the URL; otherwise the FILE
  std::string inner;                        // kRecord: the SPEC recorded
  CorpusSelection selection;                // kCorpus
};

Error bad_spec(std::string what) {
  return Error{ErrorCode::kInvalidInput, std::move(what) + ": expected " + llm_spec_forms(false) + " (docs/llm.md)"};
}

// FILE[,condition=NAME][,pool=all]: the options follow the file name, so a
// path may not itself hold ",condition=" or ",pool=".
Status parse_corpus(std::string_view rest, ParsedSpec& out) {
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
      out.selection.pool_all = true;
      out.selection.condition.clear();
    } else {
      out.selection.condition = value;
      named = true;
    }
    path.erase(at, end == std::string::npos ? std::string::npos : end - at);
  }
  if (path.empty()) return make_error(ErrorCode::kInvalidInput, "corpus: needs a file");
  out.target = std::move(path);
  return {};
}

Result<ParsedSpec> parse_spec(std::string_view spec, const LlmOptions& options) {
  spec = trim(spec);
  const size_t colon = spec.find(':');
  const std::string_view scheme = spec.substr(0, colon);
  const std::string_view rest = colon == std::string_view::npos ? "" : spec.substr(colon + 1);
  ParsedSpec out;
  if (scheme == "openai" || scheme == "openai-chat" || scheme == "llama") {
    out.kind = ParsedSpec::Kind::kHttp;
    out.format = scheme == "openai"        ? WireFormat::kOpenAi
                 : scheme == "openai-chat" ? WireFormat::kOpenAiChat
                                           : WireFormat::kLlamaNative;
    out.target = rest.empty() && scheme != "llama" ? env_or_empty("OPENAI_BASE_URL") : std::string(rest);
    if (out.target.empty())
      return tl::unexpected(bad_spec(std::string(scheme) + ": needs a URL (" + std::string(scheme) +
                                     (scheme == "llama" ? ":http://host:port" : ":http://host:port/v1, or OPENAI_BASE_URL") +
                                     ")"));
    if (out.target.find("://") == std::string::npos)
      return make_error(ErrorCode::kInvalidInput,
                        "LLM URL must start with http:// or https://: " + apprentice::quoted(out.target));
    return out;
  }
  if (scheme == "replay" && !rest.empty()) {
    out.kind = ParsedSpec::Kind::kReplay;
    out.target = std::string(rest);
    return out;
  }
  if (scheme == "record") {
    const size_t comma = rest.find(',');
    if (comma == std::string_view::npos || comma == 0 || comma + 1 == rest.size())
      return tl::unexpected(bad_spec("record: needs FILE,SPEC, e.g. record:run.jsonl,openai:http://127.0.0.1:8080/v1"));
    auto inner = parse_spec(rest.substr(comma + 1), options);  // the SPEC recorded is checked too
    if (!inner) return tl::unexpected(inner.error());
    out.kind = ParsedSpec::Kind::kRecord;
    out.target = std::string(rest.substr(0, comma));
    out.inner = std::string(rest.substr(comma + 1));
    return out;
  }
  if (scheme == "corpus" && !rest.empty()) {
    out.kind = ParsedSpec::Kind::kCorpus;
    out.selection.condition = options.corpus_condition;
    if (auto status = parse_corpus(rest, out); !status) return tl::unexpected(status.error());
    return out;
  }
  const bool known = std::any_of(std::begin(kBackends), std::end(kBackends),
                                 [&](const Backend& b) { return b.scheme == scheme; });
  return tl::unexpected(bad_spec(apprentice::quoted(spec) + (known ? " lacks what its backend needs"
                                                                   : " is not an LLM backend")));
}

std::unique_ptr<LlmClient> make_http(const ParsedSpec& parsed, const LlmOptions& options) {
  HttpOptions http;
  http.format = parsed.format;
  http.endpoint = parsed.format == WireFormat::kOpenAi       ? openai_endpoint(parsed.target)
                  : parsed.format == WireFormat::kOpenAiChat ? openai_chat_endpoint(parsed.target)
                                                             : llama_endpoint(parsed.target);
  http.wire.model = options.model.empty() ? env_or_empty("OPENAI_MODEL") : options.model;
  http.wire.seed = options.seed;
  http.api_key = options.api_key ? *options.api_key : env_or_empty("OPENAI_API_KEY");
  http.transport = options.transport;
  return std::make_unique<HttpLlmClient>(std::move(http));
}

}  // namespace

std::string llm_spec_forms(bool with_options) {
  std::string out;
  for (const Backend& backend : kBackends)
    out += (out.empty() ? "" : ", ") + std::string(backend.forms) + std::string(with_options ? backend.options : "");
  return out;
}

Status check_llm_spec(std::string_view spec) {
  auto parsed = parse_spec(spec, LlmOptions{});
  if (!parsed) return tl::unexpected(parsed.error());
  return {};
}

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

Result<ServerCheck> check_llm_server(std::string_view spec, const LlmOptions& options) {
  auto parsed = parse_spec(spec, options);
  if (!parsed) return tl::unexpected(parsed.error());
  if (parsed->kind == ParsedSpec::Kind::kRecord) return check_llm_server(parsed->inner, options);
  if (parsed->kind != ParsedSpec::Kind::kHttp) return ServerCheck{};
  std::unique_ptr<LlmClient> client = make_http(*parsed, options);
  CompletionRequest tiny;
  tiny.prompt = "Hello";
  tiny.max_tokens = 1;
  tiny.top_logprobs = 1;
  const auto started = std::chrono::steady_clock::now();
  auto answer = client->complete(tiny);
  if (!answer) return tl::unexpected(answer.error());
  ServerCheck check;
  check.asked = true;
  check.server = client->describe();
  check.took = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - started);
  check.logprobs = logprobs_arrived(*answer);
  return check;
}

std::optional<std::string> resolve_llm_spec(std::string_view flag) {
  if (!flag.empty()) return std::string(flag);
  std::string env = env_or_empty("APPRENTICE_LLM");
  if (!env.empty()) return env;
  return std::nullopt;
}

Result<std::unique_ptr<LlmClient>> make_llm_client(std::string_view spec, const LlmOptions& options) {
  auto parsed = parse_spec(spec, options);
  if (!parsed) return tl::unexpected(parsed.error());
  switch (parsed->kind) {
    case ParsedSpec::Kind::kHttp: return make_http(*parsed, options);
    case ParsedSpec::Kind::kReplay: {
      auto client = ReplayClient::open(parsed->target);
      if (!client) return tl::unexpected(client.error());
      return std::unique_ptr<LlmClient>(std::move(*client));
    }
    case ParsedSpec::Kind::kRecord: {
      auto inner = make_llm_client(parsed->inner, options);
      if (!inner) return tl::unexpected(inner.error());
      auto client = RecordingClient::open(parsed->target, std::move(*inner));
      if (!client) return tl::unexpected(client.error());
      return std::unique_ptr<LlmClient>(std::move(*client));
    }
    case ParsedSpec::Kind::kCorpus: {
      // Recorded summaries and placements (the TidyBot benchmark's) rather than goal statements.
      if (PlacementCorpusClient::recognizes(parsed->target)) {
        if (parsed->selection.pool_all || !parsed->selection.condition.empty())
          return make_error(ErrorCode::kInvalidInput, "corpus: " + parsed->target +
                                                          " holds summaries and placements, which have no conditions "
                                                          "to choose (no ,condition= or ,pool=)");
        auto placements = PlacementCorpusClient::open(parsed->target);
        if (!placements) return tl::unexpected(placements.error());
        return std::unique_ptr<LlmClient>(std::move(*placements));
      }
      auto client = CorpusClient::open(parsed->target, parsed->selection);
      if (!client) return tl::unexpected(client.error());
      return std::unique_ptr<LlmClient>(std::move(*client));
    }
  }
  return tl::unexpected(bad_spec(apprentice::quoted(spec) + " is not an LLM backend"));
}

}  // namespace apprentice::llm
