#include "teaching_session.h"

#include "agent/explanation.h"
#include "knowledge/store_engine.h"
#include "language/narration.h"
#include "language/narration_summary.h"
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
    text += ": " + language::goal_parts_met(achieved, total) + ", " + after + ".";
  } else {
    text += ", " + after + ".";
  }
  text += store_name.empty() ? " Nothing was kept: this session had no knowledge store."
                             : " What you taught me is kept in the knowledge store \"" + store_name + "\".";
  return text;
}

}  // namespace

Result<std::unique_ptr<TeachingSession>> TeachingSession::start(SessionSetup setup) {
  auto agent = make_agent_session(setup.agent, setup.scenario);
  if (!agent) return tl::unexpected(agent.error());
  auto events = SessionEvents::open(setup.log_path);
  if (!events) return tl::unexpected(events.error());
  std::unique_ptr<TeachingSession> session(
      new TeachingSession(std::move(setup), std::move(*events), std::move(*agent)));
  session->thread_ = std::thread([s = session.get()] { s->run(); });
  return session;
}

TeachingSession::TeachingSession(SessionSetup setup, std::unique_ptr<SessionEvents> events,
                                 std::unique_ptr<AgentSession> agent)
    : setup_(std::move(setup)), events_(std::move(events)), agent_(std::move(agent)) {
  // The views are called on the agent's thread, while the agent waits for
  // a reply: reading its knowledge then is safe.
  PageViews views{[this] { return describe(agent_->knowledge(), *setup_.scenario.world.domain); },
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
void TeachingSession::run() {
  const Scenario& scenario = setup_.scenario;
  events_->append({{"type", "start"}, {"world", setup_.world_name}, {"scenario", scenario.name},
                   {"store", setup_.store_name}, {"condition", setup_.agent.condition}});
  auto report = agent_->learn(*instructor_);
  const bool finished = report && !report->stopped;
  const State end_state = report ? report->end : scenario.world.state;
  const DialogueCounts counts = report ? report->counts : DialogueCounts{};
  World now = scenario.world;
  now.state = end_state;
  nlohmann::json end{{"type", "end"},
                     {"text", summary(scenario, end_state, finished, counts.instructions, setup_.store_name)},
                     {"finished", finished},
                     {"instructions", counts.instructions},
                     {"words", counts.words},
                     {"world", world_view(now)},
                     {"progress", progress(scenario, now)}};
  if (!report) end["error"] = report.error().describe();
  events_->append(std::move(end));
  ended_ = true;
  events_->close();
}

}  // namespace apprentice::serve
