#include "teaching_session.h"

#include "agent/agent.h"
#include "agent/explanation.h"
#include "experiment/experiment.h"
#include "language/narration.h"
#include "world_view.h"

namespace apprentice::serve {

namespace {

// What the agent knows, for the page: each task, goal and rule in English
// with where it came from; a goal can be forgotten by the reply "forget
// <kind>", which the agent reads like any reply.
nlohmann::json describe(const Knowledge& knowledge, const Domain& domain) {
  nlohmann::json out = nlohmann::json::array();
  for (const TaskKnowledge& task : knowledge.tasks)
    out.push_back({{"what", "task"}, {"text", explain_task(task)}, {"source", nullptr}, {"forget", nullptr}});
  for (const GoalKnowledge& goal : knowledge.goals.all())
    out.push_back({{"what", "goal"},
                   {"text", explain_goal(goal)},
                   {"source", explain_provenance(goal.provenance)},
                   {"forget", "forget " + language::spoken_category(goal.key.category)}});
  for (const Rule& rule : knowledge.rules.rules())
    out.push_back({{"what", "rule"}, {"text", explain_rule(domain, rule)}, {"source", explain_provenance(rule.provenance)},
                   {"forget", nullptr}});
  return out;
}

nlohmann::json progress(const Scenario& scenario, const World& world) {
  if (!scenario.has_intent) return nullptr;
  return {{"achieved", count_achieved_assertions(scenario, world.state)},
          {"total", scenario.goal_assertions().size()}};
}

// The end of a session in English: how much of the world's intent holds,
// after how many instructions, and where what was taught is kept.
std::string summary(const Scenario& scenario, const State& state, bool finished, int instructions,
                    const std::string& store_name) {
  std::string text = finished ? "The task is learned" : "Stopped";
  std::string after = "after " + language::count_phrase(instructions, "instruction");
  if (scenario.has_intent && !scenario.goal_assertions().empty()) {
    int achieved = count_achieved_assertions(scenario, state);
    auto total = static_cast<long long>(scenario.goal_assertions().size());
    text += ": " + std::to_string(achieved) + " of " + language::count_phrase(total, "goal assertion") +
            (achieved == 1 ? " holds, " : " hold, ") + after + ".";
  } else {
    text += ", " + after + ".";
  }
  text += store_name.empty() ? " Nothing was kept: this session had no knowledge store."
                             : " What you taught me is kept in the knowledge store \"" + store_name + "\".";
  return text;
}

}  // namespace

Result<std::unique_ptr<TeachingSession>> TeachingSession::start(SessionSetup setup) {
  std::optional<KnowledgeStore> store;
  Knowledge knowledge;
  if (setup.store_path) {
    auto opened = KnowledgeStore::open(*setup.store_path);
    if (!opened) return tl::unexpected(opened.error());
    auto loaded = opened->load(*setup.scenario.world.domain);
    if (!loaded) return tl::unexpected(loaded.error());
    knowledge = std::move(*loaded);
    store.emplace(std::move(*opened));
  }
  auto events = SessionEvents::open(setup.log_path);
  if (!events) return tl::unexpected(events.error());
  std::unique_ptr<TeachingSession> session(
      new TeachingSession(std::move(setup), std::move(*events), std::move(store), std::move(knowledge)));
  session->thread_ = std::thread([s = session.get()] { s->run(); });
  return session;
}

TeachingSession::TeachingSession(SessionSetup setup, std::unique_ptr<SessionEvents> events,
                                 std::optional<KnowledgeStore> store, Knowledge knowledge)
    : setup_(std::move(setup)), events_(std::move(events)), store_(std::move(store)), knowledge_(std::move(knowledge)) {
  // The views are called on the agent's thread, while the agent waits for
  // a reply: reading its knowledge then is safe.
  PageViews views{[this] { return agent_ ? describe(agent_->knowledge(), *setup_.scenario.world.domain) : nlohmann::json::array(); },
                  [this](const World& world) { return progress(setup_.scenario, world); }};
  instructor_ = std::make_unique<PageInstructor>(*events_, std::move(views));
  touch();
}

TeachingSession::~TeachingSession() {
  end();
  if (thread_.joinable()) thread_.join();
}

void TeachingSession::end(const std::string& why) {
  if (!why.empty() && !ended_) events_->append({{"type", "say"}, {"text", why}});
  instructor_->cancel();
}

nlohmann::json TeachingSession::description() const {
  return {{"id", setup_.id}, {"world", setup_.world_name}, {"store", setup_.store_name}, {"ended", ended()}};
}

// The agent's thread.
// TODO(face, issue 24): build the agent through the public face once it is
// on main; until then it is wired as `teach` wires it (inst+search4, the
// store, no LLM).
void TeachingSession::run() {
  const Scenario& scenario = setup_.scenario;
  events_->append({{"type", "start"}, {"world", setup_.world_name}, {"scenario", scenario.name},
                   {"store", setup_.store_name}, {"condition", "inst+search4"}});
  auto condition = parse_condition("inst+search4");
  AgentOptions options;
  options.condition = *condition;
  TaskLearningAgent agent(options, std::move(knowledge_), Understanding(), store_ ? &*store_ : nullptr, nullptr);
  agent_ = &agent;
  Simulator simulator(scenario.world);
  Dialogue dialogue(*instructor_);
  auto report = agent.learn(simulator, dialogue);
  nlohmann::json end{{"type", "end"},
                     {"text", summary(scenario, simulator.state(), report.has_value(), dialogue.counts().instructions,
                                      setup_.store_name)},
                     {"finished", report.has_value()},
                     {"instructions", dialogue.counts().instructions},
                     {"words", dialogue.counts().words},
                     {"world", world_view(simulator.world())},
                     {"progress", progress(scenario, simulator.world())}};
  if (!report && report.error().code != ErrorCode::kCancelled) end["error"] = report.error().describe();
  events_->append(std::move(end));
  agent_ = nullptr;
  ended_ = true;
  events_->close();
}

}  // namespace apprentice::serve
