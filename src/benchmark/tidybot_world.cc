#include "benchmark/tidybot_world.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include "util/text.h"

namespace apprentice::benchmark {

namespace {

// Words that tell look-alike places apart by where they are or how big.
bool is_position_or_size(std::string_view word) {
  return is_one_of(word, {"left", "right", "top", "bottom", "middle", "upper", "lower", "leftmost", "rightmost",
                          "topmost", "small", "large", "big", "little", "front", "back", "inner", "outer"});
}

std::vector<std::string> name_words(std::string_view name) {
  std::string cleaned;
  for (char c : name) {
    unsigned char u = static_cast<unsigned char>(c);
    if (c == '\'') continue;  // "Rubik's" -> "rubiks"
    cleaned += std::isalnum(u) || u >= 0x80 ? static_cast<char>(std::tolower(u)) : ' ';
  }
  std::vector<std::string> words = split_words(cleaned);
  // "The Los Angeles Times newspaper": the agent says "the" before a
  // thing's name itself.
  if (words.size() > 1 && (words.front() == "the" || words.front() == "a" || words.front() == "an"))
    words.erase(words.begin());
  return words;
}

bool is_number(std::string_view word) {
  return !word.empty() && std::all_of(word.begin(), word.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// The hyphenated name, made of ASCII letters, digits and hyphens only
// (other bytes are dropped), as the scenario format requires.
std::string hyphenated(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& word : words) {
    std::string ascii;
    for (char c : word)
      if (static_cast<unsigned char>(c) < 0x80) ascii += c;
    if (ascii.empty()) continue;
    out += (out.empty() ? "" : "-") + ascii;
  }
  return out.empty() ? std::string("thing") : out;
}

// Whether WordNet puts a sense of the noun within a few steps below a
// container or a storage space, or says near it that things are stored
// there or that it is a basin (a cabinet, a refrigerator, a sink): a place
// things go *in*. A trailing number ("bin 1") is not part of the noun.
bool holds_things_in(const language::Lexicon& lexicon, std::vector<std::string> words) {
  const language::WordNet* wordnet = lexicon.wordnet();
  while (!words.empty() && is_number(words.back())) words.pop_back();
  if (wordnet == nullptr || words.empty()) return false;
  std::vector<language::SynsetOffset> senses = wordnet->noun_senses(join(words, " "));
  if (senses.empty()) senses = wordnet->noun_senses(words.back());
  if (senses.empty())
    for (const std::string& lemma : wordnet->noun_base_forms(words.back()))
      if (senses.empty()) senses = wordnet->noun_senses(lemma);
  constexpr int kMaxSteps = 5;
  constexpr int kMaxGlossSteps = 1;  // the sense's own definition and its hypernyms'
  auto says_stored = [](const std::string& gloss) {
    for (std::string_view word : {"stored", "storage", "storing", "basin"})
      if (gloss.find(word) != std::string::npos) return true;
    return false;
  };
  for (language::SynsetOffset sense : senses) {
    auto synset = wordnet->synset(sense);
    if (!synset || synset->lexicographer_file != language::kLexArtifact) continue;
    std::vector<language::SynsetOffset> frontier{sense};
    std::set<language::SynsetOffset> seen;
    for (int step = 0; step <= kMaxSteps && !frontier.empty(); ++step) {
      std::vector<language::SynsetOffset> next;
      for (language::SynsetOffset offset : frontier) {
        if (!seen.insert(offset).second) continue;
        auto s = wordnet->synset(offset);
        if (!s) continue;
        for (const std::string& lemma : s->lemmas)
          if (lemma == "container" || lemma == "storage space") return true;
        if (step <= kMaxGlossSteps && says_stored(s->gloss)) return true;
        next.insert(next.end(), s->hypernyms.begin(), s->hypernyms.end());
      }
      frontier = std::move(next);
    }
  }
  return false;
}

// A YAML double-quoted scalar.
std::string yaml_quoted(std::string_view text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// The object names of a world, each with its category: a name ending in a
// number ("pillow 2") is another object of the kind its other words name,
// when every such object of the scenario goes where that kind goes.
std::map<std::string, std::string> categories_of(const TidyBotScenario& scenario) {
  std::map<std::string, std::string> category;
  std::map<std::string, std::set<std::string>> destinations;  // base category -> where its objects go
  std::vector<std::string> all = scenario.seen_objects;
  all.insert(all.end(), scenario.unseen_objects.begin(), scenario.unseen_objects.end());
  auto base = [](const std::string& name) {
    std::vector<std::string> words = name_words(name);
    if (words.size() > 1 && is_number(words.back())) words.pop_back();
    return hyphenated(words);
  };
  for (const std::string& name : all) destinations[base(name)].insert(scenario.destination(name));
  for (const std::string& name : all) {
    std::string kind = base(name);
    category[name] = destinations[kind].size() == 1 ? kind : item_category(name);
  }
  return category;
}

}  // namespace

std::string item_category(std::string_view name) { return hyphenated(name_words(name)); }

PlaceName place_name(std::string_view receptacle) {
  std::vector<std::string> words = name_words(receptacle);
  PlaceName name;
  std::size_t first = 0;
  while (first + 1 < words.size() && is_position_or_size(words[first])) name.properties.push_back(words[first++]);
  name.category = hyphenated(std::vector<std::string>(words.begin() + static_cast<long>(first), words.end()));
  return name;
}

std::string BenchmarkWorld::receptacle_name(ObjectId place) const {
  for (const auto& [name, id] : places)
    if (id == place) return name;
  return {};
}

Result<BenchmarkWorld> build_world(const TidyBotScenario& scenario, const std::vector<std::string>& objects,
                                   const std::filesystem::path& domain,
                                   const language::Lexicon& lexicon) {
  // Look-alike places must differ in their properties; where two names
  // would not ("shelf" and "top shelf" are fine, two "shelf" are not),
  // each keeps its whole name as its category.
  std::vector<PlaceName> names;
  for (const std::string& receptacle : scenario.receptacles) names.push_back(place_name(receptacle));
  for (std::size_t i = 0; i < names.size(); ++i)
    for (std::size_t j = 0; j < names.size(); ++j)
      if (i != j && names[i].category == names[j].category && names[i].properties == names[j].properties)
        names[i] = PlaceName{item_category(scenario.receptacles[i]), {}};

  std::string yaml = "name: " + yaml_quoted("tidybot-" + std::to_string(scenario.index)) + "\n";
  yaml += "domain: " + yaml_quoted(domain.string()) + "\n";
  yaml += "location: " + yaml_quoted(scenario.room) + "\n";
  // The cart the objects start on, named so that no receptacle shares its name.
  std::string cart = "cart";
  while (std::any_of(names.begin(), names.end(), [&](const PlaceName& n) { return n.category == cart; }))
    cart = "tidying-" + cart;
  yaml += "places:\n  - {category: " + cart + ", kind: surface}\n";
  std::map<std::string, int> counter{{cart, 1}};
  std::map<std::string, std::string> place_id;  // receptacle name -> id
  for (std::size_t i = 0; i < names.size(); ++i) {
    const PlaceName& name = names[i];
    std::vector<std::string> words = name_words(scenario.receptacles[i]);
    words.erase(words.begin(), words.begin() + static_cast<long>(name.properties.size()));
    bool in = holds_things_in(lexicon, words);
    yaml += "  - {category: " + name.category + ", kind: " + (in ? "receptacle" : "surface");
    if (!name.properties.empty()) yaml += ", properties: [" + join(name.properties, ", ") + "]";
    yaml += "}\n";
    place_id[scenario.receptacles[i]] = name.category + std::to_string(++counter[name.category]);
  }
  const std::map<std::string, std::string> category = categories_of(scenario);
  yaml += "objects:\n";
  std::map<std::string, std::string> object_id;
  std::map<std::string, std::string> goes;  // category -> place id
  for (const std::string& object : objects) {
    const std::string& c = category.at(object);
    yaml += "  - {category: " + c + ", at: " + cart + "1}\n";
    object_id[object] = c + std::to_string(++counter[c]);
    goes[c] = place_id.at(scenario.destination(object));
  }
  yaml += "task:\n  name: " + yaml_quoted("tidy " + scenario.room) + "\n  subtasks:\n    - {verb: clear, place: " + cart + "1}\n";
  yaml += "intent:\n";
  for (const auto& [c, place] : goes) yaml += "  - {subtask: clear, category: " + c + ", place: " + place + "}\n";

  auto parsed = parse_scenario(yaml, "tidybot-scenario-" + std::to_string(scenario.index) + ".yaml");
  if (!parsed)
    return tl::unexpected(prefix_error(parsed.error(), "TidyBot scenario " + std::to_string(scenario.index)));
  BenchmarkWorld world{std::move(*parsed), 0, {}, {}};
  const Universe& universe = *world.scenario.world.universe;
  world.cart = *universe.find(cart + "1");
  for (const std::string& object : objects) world.objects.emplace_back(object, *universe.find(object_id.at(object)));
  for (const std::string& receptacle : scenario.receptacles)
    world.places.emplace_back(receptacle, *universe.find(place_id.at(receptacle)));
  return world;
}

}  // namespace apprentice::benchmark
