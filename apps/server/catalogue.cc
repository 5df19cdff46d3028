#include "catalogue.h"

#include <algorithm>

#include <yaml-cpp/yaml.h>

#include "face/apprentice.h"
#include "util/file.h"
#include "util/text.h"

namespace apprentice::serve {

namespace {

std::vector<std::string> names_of(const std::vector<Named>& entries) {
  std::vector<std::string> names;
  for (const Named& e : entries) names.push_back(e.name);
  return names;
}

const Named* find(const std::vector<Named>& entries, std::string_view name) {
  auto it = std::find_if(entries.begin(), entries.end(), [&](const Named& e) { return e.name == name; });
  return it == entries.end() ? nullptr : &*it;
}

// What an uploaded world's YAML says before it is read as a scenario: its
// `domain:` with its line (1-based), and how many places and things it
// would make (each object entry's `count`, or 1), with the line of
// `objects:`. Counted first, so that a few lines asking for millions of
// things are refused before they are made. yaml-cpp's exceptions stay
// here; text that does not parse is left to the scenario reader, which
// says where.
struct Outline {
  std::optional<std::pair<std::string, int>> domain;
  std::size_t places = 0;
  std::size_t things = 0;
  int objects_line = 1;
};

std::optional<Outline> outline(std::string_view yaml) {
  try {
    YAML::Node root = YAML::Load(std::string(yaml));
    if (!root.IsMap()) return std::nullopt;
    Outline out;
    if (root["domain"] && root["domain"].IsScalar())
      out.domain = std::make_pair(root["domain"].Scalar(), root["domain"].Mark().line + 1);
    if (root["places"] && root["places"].IsSequence()) out.places = root["places"].size();
    for (const auto& entry : root)
      if (entry.first.IsScalar() && entry.first.Scalar() == "objects") out.objects_line = entry.first.Mark().line + 1;
    if (const YAML::Node objects = root["objects"]; objects && objects.IsSequence()) {
      for (const YAML::Node& o : objects) {
        long long count = 1;
        if (o.IsMap() && o["count"] && o["count"].IsScalar() && YAML::convert<long long>::decode(o["count"], count))
          count = std::max(1LL, count);
        out.things += static_cast<std::size_t>(count);
      }
    }
    return out;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

std::string store_name(std::string_view location) {
  for (std::string_view scheme : {"postgresql://", "postgres://"}) {
    if (location.substr(0, scheme.size()) != scheme) continue;
    std::string_view rest = location.substr(scheme.size());
    rest = rest.substr(0, rest.find_first_of("?#"));
    const std::size_t slash = rest.find('/');
    if (slash != std::string_view::npos && slash + 1 < rest.size()) return std::string(rest.substr(slash + 1));
    // No database named: PostgreSQL's default is the user's own.
    const std::size_t at = rest.find('@');
    std::string_view user = at == std::string_view::npos ? std::string_view() : rest.substr(0, at);
    user = user.substr(0, user.find(':'));
    return user.empty() ? std::string("postgresql") : std::string(user);
  }
  return std::filesystem::path(std::string(location)).stem().string();
}

Result<Catalogue> Catalogue::make(const std::filesystem::path& data_dir, const std::vector<std::filesystem::path>& extra_worlds,
                                  const std::vector<std::string>& stores) {
  Catalogue c;
  c.scenarios_dir_ = data_dir / "scenarios";
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(data_dir / "domains", ec))
    if (entry.path().extension() == ".pddl") c.domains_.push_back(entry.path().stem().string());
  for (const auto& entry : std::filesystem::directory_iterator(c.scenarios_dir_, ec))
    if (entry.path().extension() == ".yaml") c.worlds_.push_back({entry.path().stem().string(), entry.path().string()});
  if (ec) return make_error(ErrorCode::kNotFound, c.scenarios_dir_.string() + ": " + ec.message());
  std::sort(c.domains_.begin(), c.domains_.end());
  std::sort(c.worlds_.begin(), c.worlds_.end(), [](const Named& a, const Named& b) { return a.name < b.name; });
  for (const std::filesystem::path& path : extra_worlds) {
    // Checked now, so that a broken --scenario stops the server at once.
    if (auto loaded = load_world(path); !loaded) return tl::unexpected(loaded.error());
    std::string name = path.stem().string();
    std::erase_if(c.worlds_, [&](const Named& e) { return e.name == name; });
    c.worlds_.insert(c.worlds_.begin(), Named{name, path.string()});
    if (c.default_world_.empty()) c.default_world_ = name;
  }
  if (c.default_world_.empty()) c.default_world_ = find(c.worlds_, "tidy-kitchen") ? "tidy-kitchen" : "";
  for (const std::string& location : stores) {
    std::string name = store_name(location);
    if (find(c.stores_, name))
      return make_error(ErrorCode::kInvalidInput, "two knowledge stores are named " + apprentice::quoted(name) +
                                                      " (the page offers stores by file or database name): rename one");
    c.stores_.push_back({name, location});
  }
  if (c.stores_.size() == 1) c.default_store_ = c.stores_.front().name;
  return c;
}

Result<Scenario> Catalogue::world(std::string_view name) const {
  const Named* entry = find(worlds_, name);
  if (!entry)
    return make_error(ErrorCode::kNotFound, "this server offers no world named " + apprentice::quoted(std::string(name)) +
                                                "; it offers " + join(names_of(worlds_), ", "));
  return load_world(entry->path);
}

Result<std::optional<std::string>> Catalogue::store(std::string_view name) const {
  if (name.empty()) return std::optional<std::string>();
  const Named* entry = find(stores_, name);
  if (!entry) {
    std::string offered = stores_.empty() ? "it has none (start it with --knowledge FILE to offer one)"
                                          : "it offers " + join(names_of(stores_), ", ");
    return make_error(ErrorCode::kNotFound,
                      "this server has no knowledge store named " + apprentice::quoted(std::string(name)) + "; " + offered);
  }
  return std::optional<std::string>(entry->path);
}

Result<Scenario> Catalogue::upload(std::string_view yaml, std::string_view file_name, const UploadLimits& limits) const {
  std::string shown = std::filesystem::path(std::string(file_name)).filename().string();
  if (shown.empty()) shown = "world.yaml";
  if (yaml.size() > limits.max_bytes)
    return make_error(ErrorCode::kInvalidInput, shown + ": the world is larger than " + describe_size(limits.max_bytes) +
                                                    ", the limit for an uploaded world");
  std::vector<std::string> allowed;
  for (const std::string& d : domains_) allowed.push_back("../domains/" + d + ".pddl");
  const std::optional<Outline> said = outline(yaml);
  if (said && said->domain && std::find(allowed.begin(), allowed.end(), said->domain->first) == allowed.end())
    return make_error(ErrorCode::kInvalidInput,
                      shown + ":" + std::to_string(said->domain->second) + ": an uploaded world must use one of the server's domains: " +
                          join(allowed, " or ") + ", not " + apprentice::quoted(said->domain->first));
  if (said && said->places > limits.max_places)
    return make_error(ErrorCode::kInvalidInput, shown + ": the world has " + std::to_string(said->places) +
                                                    " places; an uploaded world may have at most " +
                                                    std::to_string(limits.max_places));
  if (said && said->things > limits.max_things)
    return make_error(ErrorCode::kInvalidInput, shown + ":" + std::to_string(said->objects_line) + ": the world has " +
                                                    std::to_string(said->things) + " things; an uploaded world may have at most " +
                                                    std::to_string(limits.max_things));
  // Read as if it were beside the shipped worlds, so that ../domains/
  // resolves to the server's own; messages name the file as uploaded.
  const std::filesystem::path source = scenarios_dir_ / shown;
  auto scenario = parse_scenario(yaml, source, {data_dir() / "domains"});
  if (!scenario) {
    Error error = scenario.error();
    std::string prefix = scenarios_dir_.string() + "/";
    for (std::size_t at; (at = error.message.find(prefix)) != std::string::npos;) error.message.erase(at, prefix.size());
    return tl::unexpected(error);
  }
  return scenario;
}

}  // namespace apprentice::serve
