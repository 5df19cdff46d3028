#include "server.h"

#include <atomic>
#include <map>
#include <ostream>
#include <thread>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "catalogue.h"
#include "knowledge/store_location.h"
#include "page_files.h"
#include "session_registry.h"
#include "util/json.h"
#include "util/text.h"

namespace apprentice::serve {

namespace {

// The header a state-changing request from the page carries. A form or an
// <img> on another site cannot set it, and a script there cannot send it
// without a CORS preflight, which this server never grants.
constexpr const char* kCsrfHeader = "X-Apprentice-Request";
constexpr const char* kTokenCookie = "apprentice_token";
// A stream of events is closed after this long, and the page's EventSource
// reconnects from the last event it saw.
constexpr auto kStreamLifetime = std::chrono::seconds(60);
// A stream waits this long for an event, and writes a comment line when
// none came. The server learns that a page went away (a closed tab, a
// dropped connection) only when a write to it fails, and the first write
// after the browser closed the connection still succeeds (the browser
// answers it with a reset): a closed page's stream ends, and frees its
// thread and its place among the streams, within two of these.
constexpr auto kStreamPoll = std::chrono::milliseconds(500);

bool is_loopback(const std::string& host) {
  return host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0;
}

bool same_secret(std::string_view a, std::string_view b) {
  // Constant time in the token's length, so that timing tells nothing.
  unsigned char diff = a.size() == b.size() ? 0 : 1;
  for (std::size_t i = 0; i < b.size(); ++i) diff |= static_cast<unsigned char>(a[i % (a.size() + 1)] ^ b[i]);
  return diff == 0;
}

std::string cookie(const httplib::Request& req, const std::string& name) {
  const std::string header = req.get_header_value("Cookie");
  std::string_view rest = header;
  while (!rest.empty()) {
    std::size_t semicolon = rest.find(';');
    std::string_view part = trim(rest.substr(0, semicolon));
    if (part.size() > name.size() && part.substr(0, name.size()) == name && part[name.size()] == '=')
      return std::string(part.substr(name.size() + 1));
    rest = semicolon == std::string_view::npos ? std::string_view() : rest.substr(semicolon + 1);
  }
  return "";
}

int status_for(const Error& error) {
  switch (error.code) {
    case ErrorCode::kInvalidInput:
    case ErrorCode::kFailedPrecondition: return 400;
    case ErrorCode::kNotFound: return 404;
    case ErrorCode::kUnavailable: return 503;
    case ErrorCode::kCancelled: return 410;
    default: return 500;
  }
}

class WebServer {
 public:
  WebServer(const ServeOptions& options, Catalogue catalogue, std::map<std::string, StaticFile> page)
      : options_(options), catalogue_(std::move(catalogue)), page_(std::move(page)), sessions_(options.limits) {
    StaticFile& index = page_["/index.html"];
    index.body = page_with_options(index.body, options_json());
    page_["/"] = index;
  }

  Status run(std::ostream& out, const std::function<bool()>& stop_requested);

 private:
  std::optional<std::pair<int, std::string>> refuse(const httplib::Request& req) const;
  void routes();
  std::string options_json() const;
  void create_session(const httplib::Request& req, httplib::Response& res);
  void post_reply(const std::string& id, const httplib::Request& req, httplib::Response& res);
  void stream_events(const std::string& id, const httplib::Request& req, httplib::Response& res);
  std::shared_ptr<TeachingSession> session_or_404(const std::string& id, httplib::Response& res);

  const ServeOptions& options_;
  Catalogue catalogue_;
  std::map<std::string, StaticFile> page_;
  SessionRegistry sessions_;
  httplib::Server http_;
  int port_ = 0;
  std::atomic<bool> stopping_{false};
  std::atomic<int> streams_{0};
};

std::string WebServer::options_json() const {
  nlohmann::json worlds = nlohmann::json::array(), stores = nlohmann::json::array();
  for (const Named& w : catalogue_.worlds()) worlds.push_back(w.name);
  for (const Named& s : catalogue_.stores()) stores.push_back(s.name);
  const ServeLimits& l = options_.limits;
  return dump_json(nlohmann::json{{"worlds", worlds},
                                  {"stores", stores},
                                  {"default_world", catalogue_.default_world()},
                                  {"default_store", catalogue_.default_store()},
                                  {"condition", options_.agent.condition},
                                  {"limits",
                                   {{"max_body_bytes", l.max_body_bytes}, {"max_world_bytes", l.world.max_bytes},
                                    {"max_world_places", l.world.max_places}, {"max_world_things", l.world.max_things},
                                    {"max_reply_chars", l.max_reply_chars}, {"max_sessions", l.max_sessions},
                                    {"idle_seconds", l.idle.count()}}}});
}

// Why a request is refused before it reaches a route, if it is: the
// status and a sentence.
std::optional<std::pair<int, std::string>> WebServer::refuse(const httplib::Request& req) const {
  const std::string host = req.get_header_value("Host");
  if (is_loopback(options_.host)) {
    // A page of another site that resolves its own name to 127.0.0.1 (DNS
    // rebinding) sends its own name as Host.
    const std::string port = ":" + std::to_string(port_);
    if (host != "127.0.0.1" + port && host != "localhost" + port && host != "[::1]" + port)
      return std::make_pair(403, "this server answers only to http://127.0.0.1" + port + "/");
  }
  if (!options_.token.empty()) {
    std::string given = req.get_header_value("X-Apprentice-Token");
    if (given.empty()) given = cookie(req, kTokenCookie);
    if (given.empty() && req.has_param("token")) given = req.get_param_value("token");
    if (!same_secret(given, options_.token))
      return std::make_pair(401, given.empty() ? "this server needs its token: open the address it printed, with ?token=..."
                                               : "the token is wrong: open the address the server printed");
  }
  const std::string origin = req.get_header_value("Origin");
  if (!origin.empty() && origin != "http://" + host)
    return std::make_pair(403, "requests from another site (" + origin + ") are refused");
  const std::string site = req.get_header_value("Sec-Fetch-Site");
  if (!site.empty() && site != "same-origin" && site != "none")
    return std::make_pair(403, "requests from another site are refused");
  if (req.method != "GET" && req.method != "HEAD") {
    if (req.get_header_value(kCsrfHeader) != "1")
      return std::make_pair(403, std::string("a request that changes something must carry the header ") + kCsrfHeader +
                                     ": 1 (the page sends it)");
    if (req.get_header_value("Content-Type").rfind("application/json", 0) != 0)
      return std::make_pair(415, "the body must be JSON (Content-Type: application/json)");
  }
  return std::nullopt;
}

std::shared_ptr<TeachingSession> WebServer::session_or_404(const std::string& id, httplib::Response& res) {
  auto session = sessions_.find(id);
  if (!session) send_error(res, 404, "there is no such session: it may have ended after being idle; start another");
  return session;
}

void WebServer::create_session(const httplib::Request& req, httplib::Response& res) {
  nlohmann::json body = nlohmann::json::parse(req.body, nullptr, false);
  if (body.is_discarded() || !body.is_object()) return send_error(res, 400, "the body is not a JSON object");
  std::string store_name = body.contains("store") && body["store"].is_string() ? body["store"].get<std::string>() : "";
  auto store = catalogue_.store(store_name);
  if (!store) return send_error(res, status_for(store.error()), store.error().message);
  Result<Scenario> scenario = make_error(ErrorCode::kInvalidInput, "say which world: \"world\" (a name) or \"upload\"");
  std::string world_name;
  if (body.contains("upload") && body["upload"].is_object() && body["upload"].contains("yaml") &&
      body["upload"]["yaml"].is_string()) {
    const nlohmann::json& upload = body["upload"];
    std::string file_name = upload.contains("name") && upload["name"].is_string() ? upload["name"].get<std::string>() : "";
    scenario = catalogue_.upload(upload["yaml"].get<std::string>(), file_name, options_.limits.world);
    if (scenario) world_name = scenario->name + " (uploaded)";
  } else if (body.contains("world") && body["world"].is_string()) {
    world_name = body["world"].get<std::string>();
    scenario = catalogue_.world(world_name);
  }
  if (!scenario) return send_error(res, status_for(scenario.error()), scenario.error().message);
  SessionSetup setup;
  setup.id = new_session_id();
  setup.world_name = world_name;
  setup.scenario = std::move(*scenario);
  setup.store_name = store_name;
  setup.agent = options_.agent;
  setup.agent.knowledge = store->value_or("");
  if (options_.log_dir) setup.log_path = *options_.log_dir / (setup.id + ".jsonl");
  auto session = sessions_.start(std::move(setup));
  if (!session) return send_error(res, status_for(session.error()), session.error().message);
  res.status = 201;
  send_body(res, dump_json((*session)->description()), "application/json");
}

void WebServer::post_reply(const std::string& id, const httplib::Request& req, httplib::Response& res) {
  auto session = session_or_404(id, res);
  if (!session) return;
  session->touch();
  nlohmann::json body = nlohmann::json::parse(req.body, nullptr, false);
  if (body.is_discarded() || !body.is_object() || !body.contains("text") || !body["text"].is_string() ||
      !body.contains("question") || !body["question"].is_number_unsigned())
    return send_error(res, 400, "a reply is {\"text\": \"...\", \"question\": N}, N the number of the question's event");
  // One line, as a terminal would send it: line breaks and other control
  // characters become spaces.
  std::string text = body["text"].get<std::string>();
  for (char& c : text)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  text = std::string(trim(text));
  if (text.empty()) return send_error(res, 400, "the reply is empty: type something first");
  if (text.size() > options_.limits.max_reply_chars)
    return send_error(res, 413, "a reply may be at most " + std::to_string(options_.limits.max_reply_chars) +
                                    " characters; this one has " + std::to_string(text.size()));
  if (auto posted = session->reply(std::move(text), body["question"].get<std::uint64_t>()); !posted)
    return send_error(res, posted.error().code == ErrorCode::kFailedPrecondition ? 409 : status_for(posted.error()),
                      posted.error().message);
  send_body(res, "{}", "application/json");
}

void WebServer::stream_events(const std::string& id, const httplib::Request& req, httplib::Response& res) {
  auto session = session_or_404(id, res);
  if (!session) return;
  // Two streams per session (a reload's new one may start before the old
  // one is seen to be gone), and never so many that replies find no thread.
  if (streams_.load() >= 2 * options_.limits.max_sessions + 8)
    return send_error(res, 503, "too many pages are open on this server; close some");
  session->touch();
  std::uint64_t after = 0;
  std::string last = req.get_header_value("Last-Event-ID");
  if (last.empty() && req.has_param("after")) last = req.get_param_value("after");
  if (!last.empty()) after = std::strtoull(last.c_str(), nullptr, 10);
  struct Stream {
    std::uint64_t next;
    std::chrono::steady_clock::time_point opened;
    bool first = true;
  };
  auto stream = std::make_shared<Stream>(Stream{after, std::chrono::steady_clock::now()});
  ++streams_;
  res.set_header("Cache-Control", "no-store");
  res.set_chunked_content_provider(
      "text/event-stream",
      [this, session, stream](std::size_t, httplib::DataSink& sink) {
        bool closed = false;
        std::vector<Event> events = stopping_ ? std::vector<Event>{}
                                              : session->events().after(stream->next, kStreamPoll, &closed);
        std::string out = stream->first ? "retry: 500\n\n" : "";
        stream->first = false;
        for (const Event& e : events) {
          out += "id: " + std::to_string(e.seq) + "\ndata: " + dump_json(e.body) + "\n\n";
          stream->next = e.seq;
        }
        if (out.empty()) out = ":\n\n";  // a comment: is the page still there?
        if (!sink.write(out.data(), out.size())) return false;
        if (stopping_ || (closed && events.empty()) || std::chrono::steady_clock::now() - stream->opened > kStreamLifetime)
          sink.done();
        return true;
      },
      [this](bool) { --streams_; });
}

void WebServer::routes() {
  http_.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    res.set_header("X-Content-Type-Options", "nosniff");
    res.set_header("Referrer-Policy", "no-referrer");
    res.set_header("X-Frame-Options", "DENY");
    if (auto refused = refuse(req)) {
      send_error(res, refused->first, refused->second);
      return httplib::Server::HandlerResponse::Handled;
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });
  http_.set_error_handler([](const httplib::Request&, httplib::Response& res) {
    if (res.has_header("Content-Type")) return;  // a route's own answer
    if (res.status == 413) return send_error(res, 413, "the request is larger than the server accepts");
    if (res.status == 404) return send_error(res, 404, "there is nothing here");
    send_error(res, res.status, "the request could not be handled");
  });
  http_.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
    send_error(res, 500, "the server failed on this request");
  });
  http_.Get(R"(/[A-Za-z0-9_-]*(\.[a-z]+)?)", [this](const httplib::Request& req, httplib::Response& res) {
    auto file = page_.find(req.path);
    if (file == page_.end()) return send_error(res, 404, "there is nothing here");
    if (!options_.token.empty() && req.has_param("token")) {
      // The token from the printed address becomes a cookie the page's
      // requests carry; the address bar then drops it.
      res.set_header("Set-Cookie", std::string(kTokenCookie) + "=" + options_.token + "; HttpOnly; SameSite=Strict; Path=/");
      res.set_redirect(req.path);
      return;
    }
    if (req.path == "/" || req.path == "/index.html")
      res.set_header("Content-Security-Policy",
                     "default-src 'self'; img-src 'self' data:; style-src 'self'; script-src 'self'; "
                     "connect-src 'self'; frame-ancestors 'none'; base-uri 'none'; form-action 'none'");
    // A file asked for by the version the page names never changes: the
    // browser keeps it. The page itself, and any other request, is checked
    // each time.
    const bool versioned = !file->second.version.empty() && req.has_param("v") &&
                           req.get_param_value("v") == file->second.version;
    res.set_header("Cache-Control", versioned ? "max-age=31536000, immutable" : "no-cache");
    send_body(res, file->second.body, file->second.type);
  });
  http_.Get("/api/options", [this](const httplib::Request&, httplib::Response& res) {
    send_body(res, options_json(), "application/json");
  });
  http_.Post("/api/sessions", [this](const httplib::Request& req, httplib::Response& res) { create_session(req, res); });
  http_.Get(R"(/api/sessions/([0-9a-f]{32}))", [this](const httplib::Request& req, httplib::Response& res) {
    if (auto session = session_or_404(req.matches[1], res)) {
      nlohmann::json d = session->description();
      d["last_event"] = session->events().last_seq();
      send_body(res, dump_json(d), "application/json");
    }
  });
  http_.Get(R"(/api/sessions/([0-9a-f]{32})/events)",
            [this](const httplib::Request& req, httplib::Response& res) { stream_events(req.matches[1], req, res); });
  http_.Post(R"(/api/sessions/([0-9a-f]{32})/reply)",
             [this](const httplib::Request& req, httplib::Response& res) { post_reply(req.matches[1], req, res); });
  http_.Get(R"(/api/sessions/([0-9a-f]{32})/log)", [this](const httplib::Request& req, httplib::Response& res) {
    if (auto session = session_or_404(req.matches[1], res)) {
      res.set_header("Content-Disposition", "attachment; filename=\"apprentice-" + session->id() + ".jsonl\"");
      send_body(res, session->events().log_text(), "application/x-ndjson");
    }
  });
}

Status WebServer::run(std::ostream& out, const std::function<bool()>& stop_requested) {
  routes();
  http_.set_payload_max_length(options_.limits.max_body_bytes);
  // SO_REUSEADDR only: httplib's default adds SO_REUSEPORT, with which a
  // second server on a taken port would share it silently instead of
  // being told the port is in use. TCP_NODELAY (which accepted sockets
  // inherit): an event is a few small writes (chunk size, data, end), and
  // Nagle's algorithm would hold the last one back for the client's
  // delayed acknowledgement, tens of milliseconds.
  http_.set_tcp_nodelay(true);
  http_.set_socket_options([](socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, reinterpret_cast<const void*>(&yes), sizeof(yes));
    setsockopt(sock, IPPROTO_TCP, TCP_NODELAY, reinterpret_cast<const void*>(&yes), sizeof(yes));
  });
  // Each open page holds a thread with its event stream; replies and loads
  // need threads beside them.
  const std::size_t threads = static_cast<std::size_t>(options_.limits.max_sessions) * 3 + 16;
  http_.new_task_queue = [threads] { return new httplib::ThreadPool(threads); };
  http_.set_keep_alive_timeout(5);
  http_.set_read_timeout(10);
  http_.set_write_timeout(10);
  try {
    port_ = options_.port == 0 ? http_.bind_to_any_port(options_.host) : options_.port;
    if (port_ < 0 || (options_.port != 0 && !http_.bind_to_port(options_.host, options_.port)))
      return make_error(ErrorCode::kIo, "cannot listen on " + options_.host + ":" + std::to_string(options_.port) +
                                            " (is another program using the port?)");
  } catch (const std::exception& e) {
    return make_error(ErrorCode::kIo, std::string("cannot listen: ") + e.what());
  }
  std::thread listener([this] {
    try {
      http_.listen_after_bind();
    } catch (const std::exception&) {
    }
  });
  while (!http_.is_running() && listener.joinable()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  out << "Teach the agent in a browser: open " << page_address(options_, port_) << "\n"
      << "Worlds offered: " << catalogue_.worlds().size() << "; knowledge stores: "
      << (catalogue_.stores().empty() ? std::string("none (nothing is kept)") : std::to_string(catalogue_.stores().size()))
      << (options_.log_dir ? "; session logs in " + options_.log_dir->string() : std::string()) << ". Ctrl-C stops.\n";
  out.flush();
  auto last_sweep = std::chrono::steady_clock::now();
  while (!stop_requested()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    auto now = std::chrono::steady_clock::now();
    if (now - last_sweep > std::chrono::milliseconds(500)) {
      sessions_.sweep(now);
      last_sweep = now;
    }
  }
  stopping_ = true;
  sessions_.end_all();
  http_.stop();
  listener.join();
  return {};
}

}  // namespace

std::string page_address(const ServeOptions& options, int port) {
  std::string host = options.host == "0.0.0.0" || options.host == "::" ? "127.0.0.1" : options.host;
  if (host.find(':') != std::string::npos) host = "[" + host + "]";
  return "http://" + host + ":" + std::to_string(port) + "/" + (options.token.empty() ? "" : "?token=" + options.token);
}

AgentSpec serve_agent_spec() {
  AgentSpec spec = default_agent_spec();
  spec.condition = "inst+search4";
  spec.instructed_always = true;  // a person is teaching, as with `teach`
  return spec;
}

namespace {

// Builds one agent from the spec, in `world`, before the server listens: a
// condition, generalization or goal-repair text that is wrong, or an LLM
// that does not answer, is then told at once rather than to the first
// person who starts a session. Once the LLM has answered, sessions do not
// ask it again before they start; when it does not answer and the LLM is
// optional, no session asks it (`out` says so).
Status check_agent(AgentSpec& spec, const Scenario& world, std::ostream& out) {
  spec.knowledge.clear();
  const bool optional = spec.llm.optional;
  spec.llm.optional = false;
  auto agent = make_agent_session(spec, world);
  spec.llm.optional = optional;
  if (!agent && agent.error().code == ErrorCode::kUnavailable && optional) {
    std::string why = agent.error().message;
    const std::string hint = " (--llm-optional goes on without it)";
    if (why.ends_with(hint)) why.resize(why.size() - hint.size());
    out << "The LLM does not answer, so the sessions go on without it (--llm-optional): " << why << ".\n";
    spec.llm.off = true;
    agent = make_agent_session(spec, world);
  }
  if (!agent) return tl::unexpected(agent.error());
  spec.llm.check_first = false;
  return {};
}

}  // namespace

Status serve(const ServeOptions& given, std::ostream& out, const std::function<bool()>& stop_requested) {
  ServeOptions options = given;
  if (!is_loopback(options.host) && options.token.empty())
    return make_error(ErrorCode::kInvalidInput, "--host " + options.host +
                                                    " lets other machines reach the page: give --token SECRET too, and "
                                                    "every request must then carry it");
  if (!options.token.empty() && options.token.size() < 16)
    return make_error(ErrorCode::kInvalidInput, "--token must be at least 16 characters, so that it cannot be guessed");
  for (char c : options.token)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_')
      return make_error(ErrorCode::kInvalidInput, "--token may hold only letters, digits, - and _ (it goes in an address)");
  if (options.log_dir) {
    std::error_code ec;
    std::filesystem::create_directories(*options.log_dir, ec);
    if (ec) return make_error(ErrorCode::kIo, options.log_dir->string() + ": " + ec.message());
  }
  if (auto s = check_household_name(options.household); !s) return tl::unexpected(s.error());
  options.agent.household = options.household;
  if (!options.agent.robot.empty())
    if (auto s = check_robot_name(options.agent.robot); !s) return tl::unexpected(s.error());
  auto catalogue = Catalogue::make(options.data_dir, options.scenarios, options.knowledge);
  if (!catalogue) return tl::unexpected(catalogue.error());
  auto page = load_page(options.data_dir / "web");
  if (!page) return tl::unexpected(page.error());
  if (catalogue->worlds().empty())
    return make_error(ErrorCode::kNotFound, (options.data_dir / "scenarios").string() + ": there are no worlds to offer");
  auto first_world = catalogue->world(catalogue->default_world().empty() ? catalogue->worlds().front().name
                                                                         : catalogue->default_world());
  if (!first_world) return tl::unexpected(first_world.error());
  if (auto checked = check_agent(options.agent, *first_world, out); !checked) return checked;
  WebServer server(options, std::move(*catalogue), std::move(*page));
  return server.run(out, stop_requested);
}

}  // namespace apprentice::serve
