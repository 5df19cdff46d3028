#include "benchmark/tidybot_scenarios.h"

#include <algorithm>
#include <set>

#include <yaml-cpp/yaml.h>

#include "util/file.h"

namespace apprentice::benchmark {

std::string TidyBotScenario::destination(std::string_view object) const {
  for (const auto* placements : {&seen_placements, &unseen_placements})
    for (const Placement& p : *placements)
      if (p.first == object) return p.second;
  return {};
}

namespace {

// Reads one scenario mapping. yaml-cpp reports problems by throwing; every
// call into it happens inside parse_tidybot_scenarios' try block.
class ScenarioReader {
 public:
  explicit ScenarioReader(std::filesystem::path source) : source_(std::move(source)) {}

  Result<TidyBotScenario> read(const YAML::Node& node, int position) const {
    if (!node.IsMap()) return fail(node, "expected a scenario: a mapping with room, receptacles, seen_objects, ...");
    static const char* const kKeys[] = {"annotator_notes", "benchmark_index", "receptacles", "room",
                                        "seen_objects", "seen_placements", "tags", "unseen_objects",
                                        "unseen_placements"};
    for (const auto& entry : node) {
      std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "";
      if (std::none_of(std::begin(kKeys), std::end(kKeys), [&](const char* k) { return key == k; })) {
        std::string list;
        for (const char* k : kKeys) list += std::string(list.empty() ? "" : ", ") + k;
        return fail(entry.first, "unknown key '" + key + "' (expected one of: " + list + ")");
      }
    }
    TidyBotScenario scenario;
    scenario.line = node.Mark().line + 1;
    scenario.index = position;
    if (node["benchmark_index"]) {
      const YAML::Node index = node["benchmark_index"];
      int value = 0;
      if (!index.IsScalar() || !YAML::convert<int>::decode(index, value) || value < 1)
        return fail(index, "expected benchmark_index: a whole number from 1");
      scenario.index = value;
    }
    auto room = text(node, "room");
    if (!room) return tl::unexpected(room.error());
    scenario.room = *room;
    auto note = text(node, "annotator_notes");
    if (!note) return tl::unexpected(note.error());
    scenario.note = *note;
    for (auto [key, out] : {std::pair{"receptacles", &scenario.receptacles},
                            std::pair{"seen_objects", &scenario.seen_objects},
                            std::pair{"unseen_objects", &scenario.unseen_objects}, std::pair{"tags", &scenario.tags}}) {
      auto words = texts(node, key);
      if (!words) return tl::unexpected(words.error());
      *out = std::move(*words);
    }
    if (scenario.receptacles.empty()) return fail(node["receptacles"], "expected at least one receptacle");
    for (const std::string& object : scenario.unseen_objects)
      if (std::find(scenario.seen_objects.begin(), scenario.seen_objects.end(), object) != scenario.seen_objects.end())
        return fail(node["unseen_objects"], "'" + object + "' is both a seen and an unseen object");
    for (auto [key, objects, out] :
         {std::tuple{"seen_placements", &scenario.seen_objects, &scenario.seen_placements},
          std::tuple{"unseen_placements", &scenario.unseen_objects, &scenario.unseen_placements}}) {
      auto placements = read_placements(node, key, *objects, scenario.receptacles);
      if (!placements) return tl::unexpected(placements.error());
      *out = std::move(*placements);
    }
    return scenario;
  }

  tl::unexpected<Error> fail(const YAML::Node& at, const std::string& message) const {
    std::string where = source_.string();
    if (at.IsDefined() && at.Mark().line >= 0)
      where += ":" + std::to_string(at.Mark().line + 1) + ":" + std::to_string(at.Mark().column + 1);
    return tl::unexpected(Error{ErrorCode::kInvalidInput, where + ": " + message});
  }

 private:
  Result<std::string> text(const YAML::Node& map, const char* key) const {
    const YAML::Node node = map[key];
    if (!node) return fail(map, std::string("missing key '") + key + "'");
    if (!node.IsScalar() || node.Scalar().empty()) return fail(node, std::string("expected a text value for '") + key + "'");
    return node.Scalar();
  }

  Result<std::vector<std::string>> texts(const YAML::Node& map, const char* key) const {
    const YAML::Node node = map[key];
    if (!node) return fail(map, std::string("missing key '") + key + "'");
    if (!node.IsSequence()) return fail(node, std::string("expected a list of names for '") + key + "'");
    std::vector<std::string> out;
    for (const YAML::Node& item : node) {
      if (!item.IsScalar() || item.Scalar().empty()) return fail(item, std::string("expected a name in '") + key + "'");
      if (std::find(out.begin(), out.end(), item.Scalar()) != out.end())
        return fail(item, "'" + item.Scalar() + "' is given twice in '" + key + "'");
      out.push_back(item.Scalar());
    }
    return out;
  }

  // [[object, receptacle], ...]: each of `objects` exactly once, each
  // receptacle one of the scenario's.
  Result<std::vector<Placement>> read_placements(const YAML::Node& map, const char* key,
                                                 const std::vector<std::string>& objects,
                                                 const std::vector<std::string>& receptacles) const {
    const YAML::Node node = map[key];
    if (!node) return fail(map, std::string("missing key '") + key + "'");
    if (!node.IsSequence()) return fail(node, std::string("expected a list of [object, receptacle] pairs for '") + key + "'");
    std::vector<Placement> out;
    std::set<std::string> placed;
    for (const YAML::Node& pair : node) {
      if (!pair.IsSequence() || pair.size() != 2 || !pair[0].IsScalar() || !pair[1].IsScalar())
        return fail(pair, "expected a placement: [object, receptacle]");
      const std::string object = pair[0].Scalar(), receptacle = pair[1].Scalar();
      if (std::find(objects.begin(), objects.end(), object) == objects.end())
        return fail(pair[0], "'" + object + "' is not one of the objects this list places");
      if (std::find(receptacles.begin(), receptacles.end(), receptacle) == receptacles.end())
        return fail(pair[1], "'" + receptacle + "' is not one of the scenario's receptacles");
      if (!placed.insert(object).second) return fail(pair[0], "'" + object + "' is placed twice");
      out.emplace_back(object, receptacle);
    }
    for (const std::string& object : objects)
      if (!placed.contains(object)) return fail(node, "'" + object + "' is not placed");
    return out;
  }

  std::filesystem::path source_;
};

}  // namespace

Result<std::vector<TidyBotScenario>> parse_tidybot_scenarios(std::string_view yaml_text,
                                                             const std::filesystem::path& source) {
  try {
    YAML::Node root = YAML::Load(std::string(yaml_text));
    ScenarioReader reader(source);
    if (!root.IsSequence()) return reader.fail(root, "expected a list of TidyBot scenarios");
    std::vector<TidyBotScenario> scenarios;
    std::set<int> indexes;
    int position = 0;
    for (const YAML::Node& node : root) {
      auto scenario = reader.read(node, ++position);
      if (!scenario) return tl::unexpected(scenario.error());
      if (!indexes.insert(scenario->index).second)
        return reader.fail(node, "benchmark_index " + std::to_string(scenario->index) + " is given twice");
      scenarios.push_back(std::move(*scenario));
    }
    if (scenarios.empty()) return make_error(ErrorCode::kInvalidInput, source.string() + ": holds no scenario");
    return scenarios;
  } catch (const YAML::Exception& e) {
    std::string where = source.string();
    if (e.mark.line >= 0) where += ":" + std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1);
    return make_error(ErrorCode::kInvalidInput, where + ": " + e.msg);
  } catch (const std::exception& e) {
    return make_error(ErrorCode::kInvalidInput, source.string() + ": " + e.what());
  }
}

Result<std::vector<TidyBotScenario>> load_tidybot_scenarios(const std::filesystem::path& path) {
  auto text = read_input_file(path);
  if (!text) return tl::unexpected(text.error());
  return parse_tidybot_scenarios(*text, path);
}

}  // namespace apprentice::benchmark
