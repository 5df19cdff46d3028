// What a session may be started with, by name only: the worlds the server
// offers (data/scenarios, and any --scenario), the knowledge stores it was
// given (--knowledge), and an uploaded world, checked like any scenario.
// Nothing a client sends names a file: a name is looked up here, and an
// uploaded world may use only the server's own domains.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "util/result.h"
#include "world/scenario.h"

namespace apprentice::serve {

struct Named {
  std::string name;  // "tidy-kitchen", "kitchen"
  std::string path;  // a file; for a store, its location (a file or postgresql://...)
};

// The name a page offers a store by: an SQLite file's stem ("kitchen" for
// stores/kitchen.sqlite), a PostgreSQL location's database ("fleet" for
// postgresql://robot@db.example:5432/fleet?sslmode=require).
std::string store_name(std::string_view location);

// What an uploaded world may be: its YAML's size, and the places and
// things it makes (a few lines with `count:` could ask for millions).
struct UploadLimits {
  std::size_t max_bytes = std::size_t{256} << 10;
  std::size_t max_places = 100;
  std::size_t max_things = 1000;
};

class Catalogue {
 public:
  // The worlds of `data_dir`/scenarios and `extra_worlds`, named by their
  // file's stem (an --scenario of the same name as a shipped one replaces
  // it); the stores by store_name(). Errors: a world that does not
  // load (kInvalidInput, kNotFound), two stores of one name (kInvalidInput).
  static Result<Catalogue> make(const std::filesystem::path& data_dir, const std::vector<std::filesystem::path>& extra_worlds,
                                const std::vector<std::string>& stores);

  const std::vector<Named>& worlds() const { return worlds_; }
  const std::vector<Named>& stores() const { return stores_; }
  // The first --scenario, else tidy-kitchen if shipped; the only store, or none.
  const std::string& default_world() const { return default_world_; }
  const std::string& default_store() const { return default_store_; }

  // The world of that name, loaded afresh. kNotFound: no world of that name
  // is offered (the message lists those that are).
  Result<Scenario> world(std::string_view name) const;
  // The store of that name (its location); "" is none. kNotFound as for
  // world().
  Result<std::optional<std::string>> store(std::string_view name) const;
  // An uploaded world (YAML text from the page, named `file_name` in
  // messages), checked as any scenario is: errors say the line and column
  // (kInvalidInput). It must be within `limits` (its size is checked
  // first, and its places and things before any is made), and its
  // `domain` must be one the server ships (../domains/NAME.pddl, as the
  // shipped worlds say), so that nothing in it names a file of the
  // server's.
  Result<Scenario> upload(std::string_view yaml, std::string_view file_name, const UploadLimits& limits) const;

 private:
  std::vector<Named> worlds_;
  std::vector<Named> stores_;
  std::vector<std::string> domains_;  // the shipped domains' stems
  std::filesystem::path scenarios_dir_;
  std::string default_world_;
  std::string default_store_;
};

}  // namespace apprentice::serve
