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

// The `domain:` of uploaded YAML, with its line (1-based), if the text is a
// mapping that has one; yaml-cpp's exceptions stay here. Text that does not
// parse is left to the scenario reader, which says where.
std::optional<std::pair<std::string, int>> domain_entry(std::string_view yaml) {
  try {
    YAML::Node root = YAML::Load(std::string(yaml));
    if (!root.IsMap() || !root["domain"] || !root["domain"].IsScalar()) return std::nullopt;
    return std::make_pair(root["domain"].Scalar(), root["domain"].Mark().line + 1);
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

Result<Scenario> Catalogue::upload(std::string_view yaml, std::string_view file_name, std::size_t max_bytes) const {
  std::string shown = std::filesystem::path(std::string(file_name)).filename().string();
  if (shown.empty()) shown = "world.yaml";
  if (yaml.size() > max_bytes)
    return make_error(ErrorCode::kInvalidInput, shown + ": the world is larger than " + describe_size(max_bytes) +
                                                    ", the limit for an uploaded world");
  std::vector<std::string> allowed;
  for (const std::string& d : domains_) allowed.push_back("../domains/" + d + ".pddl");
  if (auto domain = domain_entry(yaml);
      domain && std::find(allowed.begin(), allowed.end(), domain->first) == allowed.end())
    return make_error(ErrorCode::kInvalidInput,
                      shown + ":" + std::to_string(domain->second) + ": an uploaded world must use one of the server's domains: " +
                          join(allowed, " or ") + ", not " + apprentice::quoted(domain->first));
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
