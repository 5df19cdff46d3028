#include "fresh_corpus.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <set>
#include <sstream>

#include "language/generation.h"
#include "language/reply.h"
#include "util/text.h"

namespace apprentice::language::fresh {
namespace {

std::string spaced(std::string text) {
  std::replace(text.begin(), text.end(), '-', ' ');
  return join(split_words(to_lower(text)), " ");
}

std::string str(const nlohmann::json& j, const char* key) {
  if (!j.is_object() || !j.contains(key) || !j[key].is_string()) return "";
  return j[key].get<std::string>();
}

// The objects a label's name means: a category ("hamper", "bathtub-edge",
// "tool chest"), after property words where the world has look-alikes
// ("top drawer", "left bin"); every object of it when the name fits several.
std::vector<ObjectId> objects_named(const World& world, const std::string& name) {
  std::vector<std::string> words = split_words(to_lower(name));
  const Universe& u = *world.universe;
  for (std::size_t first = 0; first < words.size(); ++first) {
    std::string category = join(std::vector<std::string>(words.begin() + first, words.end()), "-");
    std::vector<ObjectId> out;
    for (ObjectId id = 0; id < u.size(); ++id) {
      const ObjectInfo& info = u.info(id);
      if (info.category != category) continue;
      bool all = std::all_of(words.begin(), words.begin() + first, [&](const std::string& p) {
        return std::find(info.properties.begin(), info.properties.end(), p) != info.properties.end();
      });
      if (all) out.push_back(id);
    }
    if (!out.empty()) return out;
  }
  return {};
}

// How an object is named in the acts: an item by its category, a place by
// its category and, where the world has look-alikes, its properties.
std::string canonical(const World& world, ObjectId id) {
  const Universe& u = *world.universe;
  const ObjectInfo& info = u.info(id);
  if (info.kind == ObjectKind::kItem) return info.category;
  int same = 0;
  for (ObjectId o = 0; o < u.size(); ++o) same += u.info(o).category == info.category;
  if (same == 1 || info.properties.empty()) return info.category;
  return join(info.properties, " ") + " " + info.category;
}

std::string canonical(const World& world, std::vector<ObjectId> ids) {
  std::set<std::string> names;
  for (ObjectId id : ids) names.insert(canonical(world, id));
  return join(std::vector<std::string>(names.begin(), names.end()), ",");
}

// A label's name, canonical; the name itself (with a note) when it names
// nothing here.
std::string canonical(const World& world, const std::string& name, std::string& error) {
  if (name.empty()) return "";
  std::vector<ObjectId> ids = objects_named(world, name);
  if (ids.empty()) {
    if (error.empty()) error = "the label's \"" + name + "\" names nothing in the world";
    return "?" + name;
  }
  return canonical(world, ids);
}

std::optional<ObjectId> first_named(const World& world, const std::string& name) {
  std::vector<ObjectId> ids = objects_named(world, name);
  if (ids.empty()) return std::nullopt;
  return ids.front();
}

std::string closed_word(const nlohmann::json& value) {
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  return "null";
}

// One act of a label as its lines (a goal: one line per thing).
std::vector<std::string> label_act(const World& world, const nlohmann::json& act, std::string& error) {
  const std::string kind = str(act, "act");
  if (kind == "goal") {
    std::vector<std::string> out;
    std::string place = canonical(world, str(act, "place"), error);
    std::string closed = closed_word(act.value("closed", nlohmann::json()));
    // What the world makes of the label's preposition: a thing goes in a
    // receptacle and on a surface, whichever a writer chose ("on the dish
    // rack" for a rack the world models as a receptacle).
    std::string relation = str(act, "relation");
    if (std::optional<ObjectId> at = first_named(world, str(act, "place"))) {
      const ObjectKind place_kind = world.universe->info(*at).kind;
      if (place_kind == ObjectKind::kReceptacle) relation = "in";
      if (place_kind == ObjectKind::kSurface) relation = "on";
    }
    if (!act.contains("things") || !act["things"].is_array() || act["things"].empty())
      error = "a goal act without things";
    else
      for (const auto& thing : act["things"])
        out.push_back("goal " + (thing.is_string() ? canonical(world, thing.get<std::string>(), error) : "?") + " " +
                      relation + " " + place + " closed=" + closed);
    return out;
  }
  if (kind == "task") return {"task " + spaced(str(act, "name"))};
  if (kind == "subtask") return {"subtask " + spaced(str(act, "verb")) + " " + canonical(world, str(act, "place"), error)};
  if (kind == "loop") return {"loop " + canonical(world, str(act, "place"), error)};
  if (kind == "action" || kind == "command") {
    std::string line = kind + " " + spaced(str(act, "verb")) + " " + canonical(world, str(act, "object"), error);
    if (!str(act, "place").empty()) line += " " + canonical(world, str(act, "place"), error);
    return {line};
  }
  if (kind == "choose") return {"choose " + canonical(world, str(act, "place"), error)};
  if (kind == "question") {
    std::string line = "question " + str(act, "about");
    if (!str(act, "thing").empty()) line += " " + canonical(world, str(act, "thing"), error);
    return {line};
  }
  static const std::set<std::string> kPlain = {"leave", "repeat", "part-done", "keep-going", "task-done", "yes",
                                               "no",    "undo",   "help",      "quit",       "ask-back"};
  if (kPlain.count(kind)) return {kind};
  error = "unknown act \"" + kind + "\"";
  return {"?" + kind};
}

// Appends an act: a goal's lines join a run of goal acts just before it.
void push(Acts& acts, std::vector<std::string> lines) {
  if (lines.empty()) return;
  bool goal = lines.front().starts_with("goal");
  if (goal && !acts.empty() && !acts.back().empty() && acts.back().front().starts_with("goal")) {
    acts.back().insert(acts.back().end(), lines.begin(), lines.end());
  } else {
    acts.push_back(std::move(lines));
  }
  if (goal) {
    std::sort(acts.back().begin(), acts.back().end());
    acts.back().erase(std::unique(acts.back().begin(), acts.back().end()), acts.back().end());
  }
}

std::vector<std::string> goal_lines(const World& world, const Goal& goal) {
  const Universe& u = *world.universe;
  const Vocabulary& v = world.vocabulary;
  std::vector<std::string> out;
  std::set<ObjectId> destinations;
  for (const Literal& l : goal.literals) {
    if (!l.positive || l.fact.arity != 2 || (l.fact.predicate != v.in && l.fact.predicate != v.on)) continue;
    if (u.info(l.fact.args[0]).kind != ObjectKind::kItem) continue;
    ObjectId place = l.fact.args[1];
    destinations.insert(place);
    std::string closed = "null";
    for (const Literal& c : goal.literals)
      if (c.fact.predicate == v.closed && c.fact.arity == 1 && c.fact.args[0] == place)
        closed = c.positive ? "true" : "false";
    out.push_back("goal " + canonical(world, l.fact.args[0]) + " " + (l.fact.predicate == v.in ? "in" : "on") + " " +
                  canonical(world, place) + " closed=" + closed);
  }
  // A door's state the goal sets for a place nothing goes to.
  for (const Literal& c : goal.literals)
    if (c.fact.predicate == v.closed && c.fact.arity == 1 && !destinations.count(c.fact.args[0]))
      out.push_back(std::string("goal-state ") + (c.positive ? "closed " : "open ") + canonical(world, c.fact.args[0]));
  return out;
}

std::string action_line(const World& world, const Action& action) {
  const std::string& name = world.domain->actions[action.schema].name;
  auto args = action.arguments();
  std::string verb = name;
  if (name == "pick-up" || name == "pick-up-from") verb = "pick up";
  if (name == "put-in" || name == "put-on") verb = "put";
  std::string line = "action " + verb + " " + (args.empty() ? "?" : canonical(world, args[0]));
  if (verb == "put" && args.size() > 1) line += " " + canonical(world, args[1]);
  return line;
}

// The reading as acts; nullopt when it asks back or refuses.
std::optional<Acts> reading_acts(const Grounder& grounder, const World& world, const Line& line,
                                 const ReplyContext& context, const Reply& reply, Acts acts = {}) {
  struct Visitor {
    const Grounder& grounder;
    const World& world;
    const Line& line;
    const ReplyContext& context;
    Acts& acts;
    bool operator()(const TaskNamed& r) const { return push(acts, {"task " + spaced(r.name)}), true; }
    bool operator()(const SubtaskNamed& r) const {
      return push(acts, {"subtask " + spaced(r.verb) + " " + canonical(world, r.places)}), true;
    }
    bool operator()(const LoopNamed& r) const { return push(acts, {"loop " + canonical(world, r.places)}), true; }
    bool operator()(const Finished& r) const {
      // An ending at a goal question ends the part with this thing when
      // nothing else is to come; else the dialogue asks it back ("There
      // are still 3 things on the table: ... Shall I leave them?"). The
      // agent takes it so at a proposal about the thing too (leave_as_told).
      const bool about_a_thing = line.asked == "goal" || line.asked == "yes-no";
      if (r.ending && about_a_thing) {
        if (!context.still_to_come.empty()) return false;
        return push(acts, {"part-done"}), true;
      }
      const std::string word = line.asked == "task-step"     ? "task-done"
                               : line.asked == "subtask-end" ? "part-done"
                               : about_a_thing               ? "leave"
                                                             : "finished";
      return push(acts, {word}), true;
    }
    bool operator()(const Proceed&) const {
      const std::string word = line.asked == "task-step"     ? "repeat"
                               : line.asked == "subtask-end" ? "keep-going"
                                                             : "proceed";
      return push(acts, {word}), true;
    }
    bool operator()(const GoalGiven& r) const {
      push(acts, goal_lines(world, r.goal));
      for (const Goal& g : r.others) push(acts, goal_lines(world, g));
      return true;
    }
    bool operator()(const ActionGiven& r) const {
      push(acts, {action_line(world, r.action)});
      for (const Action& a : r.more) push(acts, {action_line(world, a)});
      return true;
    }
    bool operator()(const YesNo& r) const {
      push(acts, {r.yes ? "yes" : "no"});
      // The rest is read at the question that follows: where the thing
      // proposed goes.
      if (!r.rest.empty() && context.object) {
        ReplyContext next = context;
        next.asked = Asked::kGoal;
        // As the agent reads it (language::goal_in_rest), else the rest's
        // other acts ("no, leave it").
        std::optional<GoalGiven> goal = goal_in_rest(grounder, world, context, r);
        // A yes that gives other things the same goal ("yes, and the
        // sponge too"): the yes, and their goals, as the agent learns them.
        if (goal && r.yes && context.proposal && goal->goal == *context.proposal && !goal->others.empty())
          goal = GoalGiven{goal->others.front(), std::vector<Goal>(goal->others.begin() + 1, goal->others.end())};
        Reply rest = goal ? Reply(*goal) : read_reply(grounder, world, next, r.rest);
        if (!std::holds_alternative<Unusable>(rest) && !std::holds_alternative<Ambiguous>(rest) &&
            !std::holds_alternative<YesNo>(rest)) {
          Line as_goal = line;
          as_goal.asked = "goal";
          auto more = reading_acts(grounder, world, as_goal, next, rest);
          if (more)
            for (auto& act : *more) push(acts, act);
        }
      }
      return true;
    }
    bool operator()(const Chosen& r) const { return push(acts, {"choose " + canonical(world, r.object)}), true; }
    bool operator()(const Command& r) const {
      switch (r.kind) {
        case Command::Kind::kHelp: push(acts, {"help"}); break;
        case Command::Kind::kStatus: push(acts, {"question status"}); break;
        case Command::Kind::kUndo: push(acts, {"undo"}); break;
        case Command::Kind::kQuit: push(acts, {"quit"}); break;
        case Command::Kind::kForget: push(acts, {"forget " + r.argument}); break;
        case Command::Kind::kWhatsLeft: push(acts, {"question whats-left"}); break;
        case Command::Kind::kWhy: push(acts, {"question why"}); break;
        case Command::Kind::kWhere:
          push(acts, {"question where" + (r.things.empty() ? std::string() : " " + canonical(world, r.things))});
          break;
        case Command::Kind::kDo:
          for (const Action& a : r.actions) {
            std::string line = action_line(world, a);
            push(acts, {"command" + line.substr(std::string("action").size())});
          }
          break;
      }
      return true;
    }
    bool operator()(const Ambiguous&) const { return false; }
    bool operator()(const Unusable&) const { return false; }
  };
  if (!std::visit(Visitor{grounder, world, line, context, acts}, reply)) return std::nullopt;
  return acts;
}

bool is_goal_run(const std::vector<std::string>& act) { return !act.empty() && act.front().starts_with("goal"); }

// The reading says what the label says, less some goals for other things.
bool fewer_goals(const Acts& label, const Acts& reading) {
  auto split = [](const Acts& acts, Acts& rest, std::set<std::string>& goals) {
    for (const auto& act : acts) {
      if (is_goal_run(act)) goals.insert(act.begin(), act.end());
      else rest.push_back(act);
    }
  };
  Acts label_rest, reading_rest;
  std::set<std::string> label_goals, reading_goals;
  split(label, label_rest, label_goals);
  split(reading, reading_rest, reading_goals);
  if (label_rest != reading_rest || reading_goals.size() >= label_goals.size()) return false;
  return std::includes(label_goals.begin(), label_goals.end(), reading_goals.begin(), reading_goals.end());
}

}  // namespace

std::string_view to_string(Outcome outcome) {
  switch (outcome) {
    case Outcome::kMeant: return "meant";
    case Outcome::kAskedBack: return "asked-back";
    case Outcome::kWrong: return "wrong";
  }
  return "wrong";
}

Corpus read_corpus(const std::filesystem::path& folder) {
  Corpus corpus;
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec))
    if (entry.path().extension() == ".jsonl") files.push_back(entry.path());
  if (ec) corpus.errors.push_back(folder.string() + ": " + ec.message());
  std::sort(files.begin(), files.end());
  for (const auto& path : files) {
    std::ifstream in(path);
    std::string text;
    int number = 0;
    while (std::getline(in, text)) {
      ++number;
      if (trim(text).empty()) continue;
      std::string where = path.filename().string() + ":" + std::to_string(number);
      nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
      if (j.is_discarded() || !j.is_object()) {
        corpus.errors.push_back(where + ": not a JSON object");
        continue;
      }
      Line line;
      line.file = where;
      line.id = str(j, "id");
      line.world = str(j, "world");
      line.asked = str(j, "asked");
      line.reply = str(j, "reply");
      if (j.contains("about") && j["about"].is_string()) line.about = j["about"].get<std::string>();
      line.context = j.contains("context") && j["context"].is_object() ? j["context"] : nlohmann::json::object();
      line.meaning = j.contains("meaning") ? j["meaning"] : nlohmann::json();
      if (line.id.empty() || line.world.empty() || line.asked.empty() || !j.contains("reply") ||
          !line.meaning.is_array() || line.meaning.empty()) {
        corpus.errors.push_back(where + ": a field is missing (id, world, asked, reply, meaning)");
        continue;
      }
      corpus.lines.push_back(std::move(line));
    }
  }
  return corpus;
}

const Scenario* Worlds::get(const std::string& world_file, std::string& error) {
  auto found = loaded_.find(world_file);
  if (found != loaded_.end()) return &found->second;
  std::filesystem::path own = folder_ / world_file;
  std::filesystem::path shipped = folder_ / "../../../../data/scenarios" / world_file;
  // ("domain: kitchen", as docs/scenarios.md tells a person to write: the
  // shipped domain, four folders up from a corpus's folder.)
  Result<Scenario> scenario =
      load_scenario(std::filesystem::exists(own) ? own : shipped, {folder_ / "../../../../data/domains"});
  if (!scenario) {
    error = "world " + world_file + ": " + scenario.error().message;
    return nullptr;
  }
  return &loaded_.emplace(world_file, std::move(*scenario)).first->second;
}

ReplyContext context_of(const Line& line, const World& world, std::string& error) {
  ReplyContext c;
  bool known = false;
  for (Asked a : {Asked::kTask, Asked::kTaskStep, Asked::kSubtaskEnd, Asked::kGoal, Asked::kAction, Asked::kYesNo,
                  Asked::kWhich})
    if (to_string(a) == line.asked) c.asked = a, known = true;
  if (!known) error = "unknown question kind \"" + line.asked + "\"";
  const nlohmann::json& ctx = line.context;
  // The places of the subtask under way.
  std::vector<ObjectId> subtask_places;
  if (ctx.contains("subtask") && ctx["subtask"].is_object()) {
    subtask_places = objects_named(world, str(ctx["subtask"], "place"));
    if (!str(ctx["subtask"], "verb").empty()) c.taught_subtasks.push_back(str(ctx["subtask"], "verb"));
  }
  // The thing asked about: of the category `about` (or proposed), at the
  // subtask's places if one is there.
  std::string about = line.about.value_or("");
  if (about.empty() && ctx.contains("proposal")) about = str(ctx["proposal"], "thing");
  if (!about.empty()) {
    std::vector<ObjectId> things = objects_named(world, about);
    if (things.empty()) error = "\"about\" names nothing in the world: " + about;
    for (ObjectId t : things) {
      auto at = place_of(world, t);
      if (!c.object && at && std::find(subtask_places.begin(), subtask_places.end(), *at) != subtask_places.end())
        c.object = t;
    }
    if (!c.object && !things.empty()) c.object = things.front();
  }
  // A goal of the context ({thing, place, relation, closed}) for a thing
  // of that kind, other than `not_this` where there is one.
  auto goal_of = [&](const nlohmann::json& g, std::optional<ObjectId> not_this) -> std::optional<ReplyContext::LastGoal> {
    std::vector<ObjectId> things = objects_named(world, str(g, "thing"));
    std::optional<ObjectId> place = first_named(world, str(g, "place"));
    if (things.empty() || !place) return std::nullopt;
    ObjectId thing = things.front();
    for (ObjectId t : things)
      if (t != not_this) {
        thing = t;
        break;
      }
    const Vocabulary& v = world.vocabulary;
    std::vector<Literal> literals = {Literal{Fact(str(g, "relation") == "on" ? v.on : v.in, {thing, *place}), true}};
    if (g.contains("closed") && g["closed"].is_boolean())
      literals.push_back(Literal{Fact(v.closed, {*place}), g["closed"].get<bool>()});
    return ReplyContext::LastGoal{thing, Goal(std::move(literals))};
  };
  if (ctx.contains("last_goal") && ctx["last_goal"].is_object()) {
    c.recent_place = first_named(world, str(ctx["last_goal"], "place"));
    c.last_goal = goal_of(ctx["last_goal"], c.object);
  }
  // What was taught before, as far as the line says: the last goal.
  if (c.last_goal) {
    const ReplyContext::LastGoal last = *c.last_goal;
    c.goal_of_kind = [last, &world](const std::string& kind, ObjectId object) -> std::optional<Goal> {
      if (world.universe->info(last.object).category != kind) return std::nullopt;
      std::vector<Literal> literals = last.goal.literals;
      for (Literal& l : literals)
        for (std::size_t i = 0; i < l.fact.arity; ++i)
          if (l.fact.args[i] == last.object) l.fact.args[i] = object;
      return Goal(std::move(literals));
    };
  }
  if (ctx.contains("proposal") && ctx["proposal"].is_object())
    if (auto proposed = goal_of(ctx["proposal"], std::nullopt)) c.proposal = proposed->goal;
  // Things still to come: the categories listed, at the subtask's places
  // first; else every other thing at the subtask's places.
  if (ctx.contains("still_to_come") && ctx["still_to_come"].is_array()) {
    for (const auto& kind : ctx["still_to_come"]) {
      if (!kind.is_string()) continue;
      std::vector<ObjectId> things = objects_named(world, kind.get<std::string>());
      std::stable_partition(things.begin(), things.end(), [&](ObjectId t) {
        auto at = place_of(world, t);
        return at && std::find(subtask_places.begin(), subtask_places.end(), *at) != subtask_places.end();
      });
      for (ObjectId t : things)
        if (t != c.object && std::find(c.still_to_come.begin(), c.still_to_come.end(), t) == c.still_to_come.end()) {
          c.still_to_come.push_back(t);
          break;
        }
    }
  } else {
    for (ObjectId t : world.universe->of_kind(ObjectKind::kItem)) {
      auto at = place_of(world, t);
      if (t != c.object && at && std::find(subtask_places.begin(), subtask_places.end(), *at) != subtask_places.end() &&
          (!c.last_goal || world.universe->info(t).category != world.universe->info(c.last_goal->object).category))
        c.still_to_come.push_back(t);
    }
  }
  if (ctx.contains("choices") && ctx["choices"].is_array())
    for (const auto& choice : ctx["choices"])
      if (choice.is_string())
        if (auto id = first_named(world, choice.get<std::string>())) c.choices.push_back(*id);
  return c;
}

Scored score(const Grounder& grounder, const World& world, const Line& line) {
  Scored out;
  ReplyContext context = context_of(line, world, out.error);
  for (const auto& act : line.meaning) push(out.label, label_act(world, act, out.error));
  auto start = std::chrono::steady_clock::now();
  ReplyActs read = read_acts(grounder, world, context, line.reply);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::optional<Acts> reading = Acts{};
  for (const Reply& reply : read.acts) {
    out.reply_line += (out.reply_line.empty() ? "" : " ; ") + format_reply(world, reply);
    if (reading) reading = reading_acts(grounder, world, line, context, reply, *reading);
  }
  // The further steps of the reply, read at the next question about the
  // task's steps, as the agent reads them.
  ReplyContext next = context;
  next.asked = Asked::kTaskStep;
  Line at_next = line;
  at_next.asked = "task-step";
  for (const std::string& then : read.then)
    for (const Reply& reply : read_acts(grounder, world, next, then).acts) {
      out.reply_line += " ; then " + format_reply(world, reply);
      if (reading) reading = reading_acts(grounder, world, at_next, next, reply, *reading);
    }
  const bool ask_back = out.label.size() == 1 && out.label.front() == std::vector<std::string>{"ask-back"};
  if (!reading) {
    out.outcome = ask_back ? Outcome::kMeant : Outcome::kAskedBack;
    return out;
  }
  out.reading = *reading;
  // "oh and close the fridge", labelled a one-off closing and then the
  // question asked back: a reading of the closing alone, which answers
  // nothing about the thing asked about, leaves the question to be asked
  // again, as labelled.
  bool asks_again = false;
  if (out.label.size() > 1 && out.label.back() == std::vector<std::string>{"ask-back"}) {
    Acts before(out.label.begin(), out.label.end() - 1);
    const std::string about = line.about ? "goal " + canonical(world, *line.about, out.error) + " " : "?";
    bool answers = false;
    for (const auto& act : out.reading)
      for (const std::string& part : act)
        answers = answers || part.starts_with(about) || part == "leave" || part == "yes" || part == "no";
    asks_again = out.reading == before && !answers;
  }
  if (out.reading == out.label || asks_again) out.outcome = Outcome::kMeant;
  else if (!ask_back && fewer_goals(out.label, out.reading)) out.outcome = Outcome::kAskedBack;
  else out.outcome = Outcome::kWrong;
  return out;
}

void add(Report& report, const Line& line, Outcome outcome) {
  auto count = [&](Tally& t) {
    (outcome == Outcome::kMeant ? t.meant : outcome == Outcome::kAskedBack ? t.asked_back : t.wrong) += 1;
  };
  std::set<std::string> kinds;
  for (const auto& act : line.meaning) kinds.insert(str(act, "act"));
  // A correction is an undo with what replaces it.
  if (kinds.count("undo") && line.meaning.size() > 1) kinds.insert("correction");
  for (const std::string& kind : kinds) count(report.by_act[kind]);
  count(report.by_asked[line.asked]);
  count(report.overall);
}

std::string format_report(const Report& report) {
  std::ostringstream out;
  auto percent = [](int n, int of) {
    std::ostringstream p;
    p.setf(std::ios::fixed);
    p.precision(1);
    p << (of == 0 ? 0.0 : 100.0 * n / of) << "%";
    return p.str();
  };
  auto table = [&](const std::string& heading, const std::map<std::string, Tally>& rows) {
    out << "| " << heading << " | lines | understood as meant | asked back | acted on wrongly |\n";
    out << "|---|---:|---:|---:|---:|\n";
    for (const auto& [name, t] : rows)
      out << "| " << name << " | " << t.total() << " | " << t.meant << " | " << t.asked_back << " | " << t.wrong
          << " |\n";
    const Tally& o = report.overall;
    out << "| **all lines** | **" << o.total() << "** | **" << o.meant << " (" << percent(o.meant, o.total())
        << ")** | **" << o.asked_back << "** | **" << o.wrong << " (" << percent(o.wrong, o.total()) << ")** |\n";
  };
  table("act", report.by_act);
  out << "\n";
  table("question", report.by_asked);
  return out.str();
}

}  // namespace apprentice::language::fresh
