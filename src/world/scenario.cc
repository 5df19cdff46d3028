#include "world/scenario.h"

#include <algorithm>
#include <map>
#include <set>

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include "util/text.h"
#include "world/pddl.h"

namespace apprentice {

bool Subtask::covers(ObjectId place) const {
  return std::find(places.begin(), places.end(), place) != places.end();
}

const IntentEntry* Scenario::find_intent(std::string_view subtask, std::string_view category) const {
  for (const IntentEntry& e : intent)
    if (e.subtask == subtask && e.category == category) return &e;
  return nullptr;
}

const IntentEntry* Scenario::intent_for(std::string_view subtask, ObjectId object) const {
  const std::string& category = world.universe->info(object).category;
  const Subtask* own = subtask_of(object);
  const IntentEntry* first = nullptr;
  for (const IntentEntry& e : intent) {
    if (e.subtask != subtask || e.category != category) continue;
    if (own != nullptr && e.subtask_index < task.subtasks.size() && &task.subtasks[e.subtask_index] == own) return &e;
    if (first == nullptr) first = &e;
  }
  return first;
}

std::optional<Goal> Scenario::intended_goal(std::string_view subtask, ObjectId object) const {
  const IntentEntry* entry = intent_for(subtask, object);
  if (entry == nullptr) return std::nullopt;
  bool surface = world.universe->info(entry->place).kind == ObjectKind::kSurface;
  std::vector<Literal> literals{Literal{Fact(surface ? world.vocabulary.on : world.vocabulary.in, {object, entry->place}), true}};
  if (entry->closed) literals.push_back(Literal{Fact(world.vocabulary.closed, {entry->place}), true});
  return Goal(std::move(literals));
}

const Subtask* Scenario::subtask_of(ObjectId object) const {
  const Vocabulary& v = world.vocabulary;
  for (const Subtask& s : task.subtasks) {
    for (ObjectId place : s.places)
      if (world.state.holds(Fact(v.on, {object, place})) || world.state.holds(Fact(v.in, {object, place})))
        return &s;
  }
  return nullptr;
}

std::vector<ObjectId> Scenario::objects_to_tidy() const {
  std::vector<ObjectId> out;
  for (ObjectId o : world.universe->of_kind(ObjectKind::kItem))
    if (subtask_of(o) != nullptr) out.push_back(o);
  return out;
}

std::vector<Literal> Scenario::goal_assertions() const {
  std::vector<Literal> out;
  for (ObjectId o : objects_to_tidy()) {
    auto goal = intended_goal(subtask_of(o)->verb, o);
    if (goal) out.insert(out.end(), goal->literals.begin(), goal->literals.end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

namespace {

// yaml-cpp keeps every entry of a mapping but answers a lookup with the
// first, so a key given twice would silently lose its second value. Every
// mapping of the tree is checked before anything is read, each once: an
// alias (*name) is the very node its anchor (&name) made, so a list of
// aliases to lists of aliases, a few hundred bytes, would otherwise be
// walked billions of times. `seen`: the text positions of the lists and
// mappings already checked (each starts at a position of its own).
std::optional<std::pair<YAML::Mark, std::string>> find_duplicate_key(const YAML::Node& node, std::set<int>& seen) {
  if (!node.IsSequence() && !node.IsMap()) return std::nullopt;
  if (node.Mark().pos >= 0 && !seen.insert(node.Mark().pos).second) return std::nullopt;
  if (node.IsSequence()) {
    for (const YAML::Node& child : node)
      if (auto found = find_duplicate_key(child, seen)) return found;
    return std::nullopt;
  }
  std::map<std::string, YAML::Mark> keys;
  for (const auto& entry : node) {
    std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "";
    if (entry.first.IsScalar()) {
      auto [where, fresh] = keys.emplace(key, entry.first.Mark());
      if (!fresh)
        return std::pair{entry.first.Mark(), "the key '" + key + "' is given twice in one mapping (first at line " +
                                                 std::to_string(where->second.line + 1) + ", column " +
                                                 std::to_string(where->second.column + 1) + ")"};
    }
    if (auto found = find_duplicate_key(entry.second, seen)) return found;
  }
  return std::nullopt;
}

// Builds a scenario from a YAML tree. yaml-cpp reports problems by
// throwing; every call into it happens inside parse_scenario's try block.
class ScenarioBuilder {
 public:
  ScenarioBuilder(std::filesystem::path source, const std::vector<std::filesystem::path>& domain_folders)
      : source_(std::move(source)), domain_folders_(domain_folders) {}

  Result<Scenario> build(const YAML::Node& root) {
    if (!root.IsMap()) return fail(root, "expected a mapping with name, domain, places, objects, task and intent");
    std::set<int> checked;
    if (auto duplicate = find_duplicate_key(root, checked)) return fail_at(duplicate->first, duplicate->second);
    if (auto s = check_keys(root, {"name", "domain", "location", "reference", "places", "objects", "facts", "task",
                                   "intent"});
        !s)
      return tl::unexpected(s.error());
    Scenario scenario;
    scenario.source = source_;
    auto name = required_string(root, "name");
    if (!name) return tl::unexpected(name.error());
    scenario.name = *name;
    if (root["location"]) {
      auto location = required_string(root, "location");
      if (!location) return tl::unexpected(location.error());
      scenario.world.location = *location;
    } else {
      scenario.world.location = "kitchen";
    }
    if (root["reference"]) {
      auto reference = required_string(root, "reference");
      if (!reference) return tl::unexpected(reference.error());
      if (*reference != "table3")
        return fail(root["reference"], "expected reference: table3 (the paper's kitchen), not '" + *reference + "'");
      scenario.reference = *reference;
    }
    if (auto s = load_domain(root, scenario); !s) return tl::unexpected(s.error());
    if (auto s = read_places(root, scenario); !s) return tl::unexpected(s.error());
    if (auto s = read_objects(root, scenario); !s) return tl::unexpected(s.error());
    if (auto s = read_facts(root, scenario); !s) return tl::unexpected(s.error());
    if (auto s = read_task(root, scenario); !s) return tl::unexpected(s.error());
    if (auto s = read_intent(root, scenario); !s) return tl::unexpected(s.error());
    scenario.world.universe = std::make_shared<const Universe>(std::move(universe_));
    scenario.world.state = State(std::move(facts_));
    if (auto s = check_intent_complete(scenario); !s) return tl::unexpected(s.error());
    return scenario;
  }

 private:
  tl::unexpected<Error> fail(const YAML::Node& at, const std::string& message) const {
    return fail_at(at.IsDefined() ? at.Mark() : YAML::Mark::null_mark(), message);
  }

  tl::unexpected<Error> fail_at(const YAML::Mark& mark, const std::string& message) const {
    std::string where = source_.string();
    if (mark.line >= 0) where += ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
    return tl::unexpected(Error{ErrorCode::kInvalidInput, where + ": " + message});
  }

  Status check_keys(const YAML::Node& map, std::initializer_list<const char*> allowed) const {
    for (const auto& entry : map) {
      auto key = entry.first.as<std::string>();
      if (std::none_of(allowed.begin(), allowed.end(), [&](const char* a) { return key == a; })) {
        std::string list;
        for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
        return fail(entry.first, "unknown key '" + key + "' (expected one of: " + list + ")");
      }
    }
    return {};
  }

  Result<std::string> required_string(const YAML::Node& map, const char* key) const {
    const YAML::Node node = map[key];
    if (!node) return fail(map, std::string("missing key '") + key + "'");
    if (!node.IsScalar() || node.Scalar().empty()) return fail(node, std::string("expected a text value for '") + key + "'");
    return node.Scalar();
  }

  static bool is_name(std::string_view text) {
    return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
      return std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '-';
    });
  }

  Result<std::string> required_name(const YAML::Node& map, const char* key) const {
    auto text = required_string(map, key);
    if (!text) return text;
    if (!is_name(*text))
      return fail(map[key], std::string("expected a lower-case hyphenated name for '") + key + "', not '" + *text + "'");
    return text;
  }

  Result<bool> optional_bool(const YAML::Node& map, const char* key, bool fallback) const {
    const YAML::Node node = map[key];
    if (!node) return fallback;
    bool value = false;
    if (!node.IsScalar() || !YAML::convert<bool>::decode(node, value))
      return fail(node, std::string("expected true or false for '") + key + "'");
    return value;
  }

  // `properties: [top, wooden]`: lower-case words, each once.
  Result<std::vector<std::string>> optional_properties(const YAML::Node& map) const {
    const YAML::Node node = map["properties"];
    std::vector<std::string> words;
    if (!node) return words;
    if (!node.IsSequence()) return fail(node, "expected 'properties': a list of words such as [top] or [blue, small]");
    for (const YAML::Node& word : node) {
      if (!word.IsScalar() || !is_name(word.Scalar()))
        return fail(word, "expected a property: a lower-case word such as top, blue or left");
      if (std::find(words.begin(), words.end(), word.Scalar()) != words.end())
        return fail(word, "the property '" + word.Scalar() + "' is given twice");
      words.push_back(word.Scalar());
    }
    return words;
  }

  // The domain's file: relative to the scenario; a bare name that names no
  // file there ("kitchen"), NAME.pddl in the first domain folder that has it.
  std::filesystem::path domain_file(const std::string& named) const {
    std::error_code ec;
    const std::filesystem::path beside = source_.parent_path() / named;
    const bool bare = named.find('/') == std::string::npos && std::filesystem::path(named).extension().empty();
    if (!bare || std::filesystem::exists(beside, ec)) return beside;
    for (const std::filesystem::path& folder : domain_folders_)
      if (std::filesystem::exists(folder / (named + ".pddl"), ec)) return folder / (named + ".pddl");
    return beside;
  }

  Status load_domain(const YAML::Node& root, Scenario& scenario) {
    auto path = required_string(root, "domain");
    if (!path) return tl::unexpected(path.error());
    scenario.domain_path = domain_file(*path);
    auto domain = read_domain_file(scenario.domain_path);
    if (!domain) {
      // Keep the code: a missing domain file is kNotFound, as a missing scenario is.
      auto error = fail(root["domain"], "cannot load the domain: " + domain.error().message);
      error.value().code = domain.error().code;
      return error;
    }
    auto vocabulary = Vocabulary::resolve(*domain);
    if (!vocabulary) return fail(root["domain"], vocabulary.error().message);
    for (ObjectKind kind : {ObjectKind::kItem, ObjectKind::kReceptacle, ObjectKind::kSurface}) {
      auto id = domain->find_type(type_name(kind));
      if (!id) return fail(root["domain"], "the domain must declare the type " + std::string(type_name(kind)));
      types_[kind] = *id;
    }
    scenario.world.vocabulary = *vocabulary;
    scenario.world.domain = std::make_shared<const Domain>(std::move(*domain));
    vocabulary_ = *vocabulary;
    return {};
  }

  std::string next_id(const std::string& category) { return category + std::to_string(++counters_[category]); }

  // Adds an object under the next id of its category. Categories ending in
  // a digit can clash ("cup" 11 times and "cup1" both make cup11): that is
  // bad input, refused here rather than left to Universe::add's check.
  Result<ObjectId> add_object(const YAML::Node& at, ObjectInfo info) {
    info.id = next_id(info.category);
    if (universe_.find(info.id))
      return fail(at, "two objects would have the id " + info.id + " (a category ending in a digit clashes with " +
                          "another category's numbered ids)");
    return universe_.add(std::move(info));
  }

  // Look-alike places (one category) that carry properties must differ in
  // them: "the top drawer" has to name one drawer.
  Status check_told_apart(const YAML::Node& at, ObjectId place) const {
    const ObjectInfo& info = universe_.info(place);
    for (ObjectId other : universe_.with_category(info.category)) {
      if (other == place) continue;
      const ObjectInfo& o = universe_.info(other);
      if (o.properties == info.properties && !info.properties.empty())
        return fail(at, info.id + " has the same properties as " + o.id + ", so no one could tell them apart");
    }
    return {};
  }

  Status read_places(const YAML::Node& root, Scenario&) {
    const YAML::Node places = root["places"];
    if (!places || !places.IsSequence() || places.size() == 0)
      return fail(places ? places : root, "expected 'places': a list of surfaces and receptacles");
    for (const YAML::Node& p : places) {
      if (!p.IsMap()) return fail(p, "expected a place such as {category: fridge, kind: receptacle, door: closed}");
      if (auto s = check_keys(p, {"category", "kind", "door", "properties"}); !s) return s;
      auto category = required_name(p, "category");
      if (!category) return tl::unexpected(category.error());
      auto kind_text = required_string(p, "kind");
      if (!kind_text) return tl::unexpected(kind_text.error());
      auto kind = parse_object_kind(*kind_text);
      if (!kind || *kind == ObjectKind::kItem) return fail(p["kind"], "expected kind 'surface' or 'receptacle', not '" + *kind_text + "'");
      auto properties = optional_properties(p);
      if (!properties) return tl::unexpected(properties.error());
      auto added = add_object(p, ObjectInfo{"", *category, *kind,
                                            types_[*kind], std::move(*properties)});
      if (!added) return tl::unexpected(added.error());
      ObjectId id = *added;
      if (auto s = check_told_apart(p, id); !s) return s;
      facts_.push_back(Fact(*kind == ObjectKind::kSurface ? vocabulary_.surface : vocabulary_.receptacle, {id}));
      if (const YAML::Node door = p["door"]) {
        if (*kind != ObjectKind::kReceptacle) return fail(door, "only a receptacle can have a door");
        std::string state = door.IsScalar() ? door.Scalar() : "";
        if (state != "open" && state != "closed") return fail(door, "expected door: open or door: closed");
        facts_.push_back(Fact(vocabulary_.openable, {id}));
        if (state == "closed") facts_.push_back(Fact(vocabulary_.closed, {id}));
      }
    }
    facts_.push_back(Fact(vocabulary_.handempty, std::initializer_list<ObjectId>{}));
    return {};
  }

  Result<ObjectId> place_named(const YAML::Node& map, const char* key) const {
    auto name = required_string(map, key);
    if (!name) return tl::unexpected(name.error());
    auto id = universe_.find(*name);
    if (!id || universe_.info(*id).kind == ObjectKind::kItem)
      return fail(map[key], "expected the id of a place, such as table1; there is no place '" + *name + "'");
    return *id;
  }

  // A subtask's place: the id of one place, or a category of places
  // meaning every place of it.
  Result<std::vector<ObjectId>> places_named(const YAML::Node& map, const char* key) const {
    auto name = required_string(map, key);
    if (!name) return tl::unexpected(name.error());
    if (auto id = universe_.find(*name); id && universe_.info(*id).kind != ObjectKind::kItem)
      return std::vector<ObjectId>{*id};
    std::vector<ObjectId> places;
    for (ObjectId id : universe_.with_category(*name))
      if (universe_.info(id).kind != ObjectKind::kItem) places.push_back(id);
    if (places.empty())
      return fail(map[key], "expected the id of a place, such as table1, or a category of places, such as bag; "
                            "there is no place '" + *name + "'");
    return places;
  }

  Status read_objects(const YAML::Node& root, Scenario&) {
    const YAML::Node objects = root["objects"];
    if (!objects || !objects.IsSequence()) return fail(objects ? objects : root, "expected 'objects': a list");
    for (const YAML::Node& o : objects) {
      if (!o.IsMap()) return fail(o, "expected an object such as {category: ketchup, at: table1}");
      if (auto s = check_keys(o, {"category", "at", "count", "properties"}); !s) return s;
      auto category = required_name(o, "category");
      if (!category) return tl::unexpected(category.error());
      auto place = place_named(o, "at");
      if (!place) return tl::unexpected(place.error());
      int count = 1;
      if (o["count"] && (!YAML::convert<int>::decode(o["count"], count) || count < 1 || count > 100000))
        return fail(o["count"], "expected a count between 1 and 100000");
      auto properties = optional_properties(o);
      if (!properties) return tl::unexpected(properties.error());
      bool on_surface = universe_.info(*place).kind == ObjectKind::kSurface;
      for (int i = 0; i < count; ++i) {
        auto added = add_object(o, ObjectInfo{"", *category, ObjectKind::kItem, types_[ObjectKind::kItem], *properties});
        if (!added) return tl::unexpected(added.error());
        ObjectId id = *added;
        object_marks_[id] = o.Mark();
        facts_.push_back(Fact(vocabulary_.grabbable, {id}));
        facts_.push_back(Fact(on_surface ? vocabulary_.on : vocabulary_.in, {id, *place}));
      }
    }
    return {};
  }

  // facts: further initial facts, in PDDL, over the predicates a domain adds
  // to the kitchen's (stacked dishes, a drawer inside a cupboard). Where
  // places and objects are, and doors, come from places and objects only.
  Status read_facts(const YAML::Node& root, Scenario& scenario) {
    const YAML::Node facts = root["facts"];
    if (!facts) return {};
    if (!facts.IsSequence()) return fail(facts, "expected 'facts': a list such as ['(stacked bowl1 plate1)']");
    const Domain& domain = *scenario.world.domain;
    const Vocabulary& v = vocabulary_;
    const PredicateId own[] = {v.on, v.in, v.holding, v.handempty, v.closed, v.grabbable, v.openable, v.receptacle, v.surface};
    for (const YAML::Node& f : facts) {
      if (!f.IsScalar()) return fail(f, "expected a fact such as (stacked bowl1 plate1)");
      auto parsed = parse_goal(domain, universe_, f.Scalar());
      if (!parsed) return fail(f, parsed.error().message);
      for (const Literal& l : parsed->literals) {
        if (!l.positive) return fail(f, "expected facts that hold, not (not ...)");
        if (std::find(std::begin(own), std::end(own), l.fact.predicate) != std::end(own))
          return fail(f, "(" + domain.predicates[l.fact.predicate].name +
                             " ...) comes from places and objects, not from facts");
        facts_.push_back(l.fact);
      }
    }
    return {};
  }

  Status read_task(const YAML::Node& root, Scenario& scenario) {
    const YAML::Node task = root["task"];
    if (!task) return {};  // a world for a person to teach in
    if (!task.IsMap()) return fail(task, "expected 'task': {name: ..., subtasks: [...]}");
    if (auto s = check_keys(task, {"name", "subtasks"}); !s) return s;
    auto name = required_string(task, "name");
    if (!name) return tl::unexpected(name.error());
    scenario.task.name = *name;
    const YAML::Node subtasks = task["subtasks"];
    if (!subtasks || !subtasks.IsSequence() || subtasks.size() == 0)
      return fail(subtasks ? subtasks : task, "expected 'subtasks': a list of {verb, place}");
    for (const YAML::Node& s : subtasks) {
      if (!s.IsMap()) return fail(s, "expected a subtask such as {verb: clear, place: table1}");
      if (auto st = check_keys(s, {"verb", "place"}); !st) return st;
      auto verb = required_name(s, "verb");
      if (!verb) return tl::unexpected(verb.error());
      // A verb may come again with other places ("clear" the floor, then
      // "clear" the counter); the intent then says which with `from`.
      auto places = places_named(s, "place");
      if (!places) return tl::unexpected(places.error());
      for (const Subtask& other : scenario.task.subtasks)
        for (ObjectId place : *places)
          if (other.covers(place))
            return fail(s["place"], universe_.name(place) + " is already the place of subtask '" + other.verb + "'");
      scenario.task.subtasks.push_back(Subtask{*verb, std::move(*places)});
    }
    return {};
  }

  // Where an intent entry sends objects: `place:` (a surface or a
  // receptacle) or, as before, `receptacle:`.
  Result<ObjectId> destination(const YAML::Node& e) const {
    if (e["place"] && e["receptacle"])
      return fail(e["receptacle"], "give either 'place' or 'receptacle', not both");
    if (e["receptacle"]) {
      auto receptacle = place_named(e, "receptacle");
      if (!receptacle) return receptacle;
      if (universe_.info(*receptacle).kind != ObjectKind::kReceptacle)
        return fail(e["receptacle"], "expected a receptacle; " + universe_.name(*receptacle) +
                                         " is a surface (write place: " + universe_.name(*receptacle) + ")");
      return receptacle;
    }
    if (!e["place"]) return fail(e, "missing key 'place' (where such objects go, such as fridge1 or shelf1)");
    return place_named(e, "place");
  }

  // The subtask an intent entry is about: the one with its verb, or, where
  // several have it, the one whose places `from` names.
  Result<std::size_t> subtask_index(const YAML::Node& e, const TaskStructure& task, const std::string& verb) const {
    std::vector<std::size_t> with_verb;
    for (std::size_t i = 0; i < task.subtasks.size(); ++i)
      if (task.subtasks[i].verb == verb) with_verb.push_back(i);
    if (with_verb.empty()) return fail(e["subtask"], "no subtask '" + verb + "' in the task");
    if (!e["from"]) {
      if (with_verb.size() == 1) return with_verb.front();
      std::vector<std::string> places;
      for (std::size_t i : with_verb) places.push_back(universe_.name(task.subtasks[i].places.front()));
      return fail(e, "the task has " + std::to_string(with_verb.size()) + " subtasks '" + verb +
                         "'; say which with 'from', the place it empties (" + join(places, " or ") + ")");
    }
    auto from = places_named(e, "from");
    if (!from) return tl::unexpected(from.error());
    for (std::size_t i : with_verb)
      if (std::all_of(from->begin(), from->end(), [&](ObjectId p) { return task.subtasks[i].covers(p); })) return i;
    return fail(e["from"], "no subtask '" + verb + "' empties " + universe_.name(from->front()));
  }

  Status read_intent(const YAML::Node& root, Scenario& scenario) {
    const YAML::Node intent = root["intent"];
    if (!intent) return {};  // the person teaching is the authority
    if (!intent.IsSequence()) return fail(intent, "expected 'intent': a list");
    if (!root["task"]) return fail(intent, "an intent needs a 'task' whose subtasks it names");
    scenario.has_intent = true;
    for (const YAML::Node& e : intent) {
      if (!e.IsMap()) return fail(e, "expected {subtask, category, place, closed}");
      if (auto s = check_keys(e, {"subtask", "from", "category", "place", "receptacle", "closed"}); !s) return s;
      IntentEntry entry;
      auto subtask = required_name(e, "subtask");
      if (!subtask) return tl::unexpected(subtask.error());
      auto index = subtask_index(e, scenario.task, *subtask);
      if (!index) return tl::unexpected(index.error());
      auto category = required_name(e, "category");
      if (!category) return tl::unexpected(category.error());
      if (std::any_of(scenario.intent.begin(), scenario.intent.end(),
                      [&](const IntentEntry& other) { return other.subtask_index == *index && other.category == *category; }))
        return fail(e, "intent for (" + *subtask + ", " + *category + ") is given twice");
      auto place = destination(e);
      if (!place) return tl::unexpected(place.error());
      auto closed = optional_bool(e, "closed", false);
      if (!closed) return tl::unexpected(closed.error());
      if (*closed && std::find(facts_.begin(), facts_.end(), Fact(vocabulary_.openable, {*place})) == facts_.end())
        return fail(e["closed"], universe_.name(*place) + " has no door, so it cannot end closed");
      entry.subtask = *subtask;
      entry.subtask_index = *index;
      entry.category = *category;
      entry.place = *place;
      entry.closed = *closed;
      scenario.intent.push_back(std::move(entry));
    }
    return {};
  }

  Status check_intent_complete(const Scenario& scenario) const {
    if (!scenario.has_intent) return {};
    for (ObjectId o : scenario.world.universe->of_kind(ObjectKind::kItem)) {
      const Subtask* s = scenario.subtask_of(o);
      if (s == nullptr) continue;
      const std::string& category = scenario.world.universe->info(o).category;
      const auto index = static_cast<std::size_t>(s - scenario.task.subtasks.data());
      if (std::none_of(scenario.intent.begin(), scenario.intent.end(),
                       [&](const IntentEntry& e) { return e.subtask_index == index && e.category == category; })) {
        auto mark = object_marks_.find(o);
        return fail_at(mark == object_marks_.end() ? YAML::Mark::null_mark() : mark->second,
                       "the intent says nothing about " + category + " for subtask " + s->verb + " (object " +
                           scenario.world.universe->name(o) + ")");
      }
    }
    return {};
  }

  std::filesystem::path source_;
  const std::vector<std::filesystem::path>& domain_folders_;
  Universe universe_;
  std::vector<Fact> facts_;
  Vocabulary vocabulary_;
  std::map<ObjectKind, TypeId> types_;
  std::map<std::string, int> counters_;
  std::map<ObjectId, YAML::Mark> object_marks_;  // where each item was declared
};

}  // namespace

Result<Scenario> parse_scenario(std::string_view yaml_text, const std::filesystem::path& source,
                                const std::vector<std::filesystem::path>& domain_folders) {
  try {
    YAML::Node root = YAML::Load(std::string(yaml_text));
    return ScenarioBuilder(source, domain_folders).build(root);
  } catch (const YAML::DeepRecursion& e) {
    // yaml-cpp's own message is "bad file"; a scenario nests four levels.
    std::string where = source.string();
    if (e.mark.line >= 0) where += ":" + std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1);
    return make_error(ErrorCode::kInvalidInput,
                      where + ": the YAML is nested too deeply (a scenario needs only a few levels of lists and mappings)");
  } catch (const YAML::Exception& e) {
    std::string where = source.string();
    if (e.mark.line >= 0) where += ":" + std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1);
    return make_error(ErrorCode::kInvalidInput, where + ": " + e.msg);
  } catch (const std::exception& e) {
    return make_error(ErrorCode::kInvalidInput, source.string() + ": " + e.what());
  }
}

Result<Scenario> load_scenario(const std::filesystem::path& path,
                               const std::vector<std::filesystem::path>& domain_folders) {
  auto text = read_text_file(path);
  if (!text) return tl::unexpected(text.error());
  return parse_scenario(*text, path, domain_folders);
}

}  // namespace apprentice
