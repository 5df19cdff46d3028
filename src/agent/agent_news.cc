// What other robots learned while this agent runs: the store's news
// (KnowledgeStore::news), taken into the agent's knowledge before each
// object and said once per kind.
#include <algorithm>

#include "agent/agent.h"
#include "agent/session.h"
#include "language/narration_steps.h"

namespace apprentice {

void TaskLearningAgent::Session::take_news() {
  KnowledgeStore* store = agent_.watched_;
  if (store == nullptr) return;
  auto news = store->news(*world().domain);
  // A look that fails (the server is restarting) is not the lesson's
  // failure: the agent goes on with what it knows and looks again at the
  // next object.
  if (!news || news->empty()) return;
  // The new kinds, by the robot that learned them, in the order heard.
  std::vector<std::pair<std::string, std::vector<std::string>>> by_robot;
  for (std::size_t i = 0; i < news->goals.size(); ++i) {
    GoalKnowledge& goal = news->goals[i];
    const GoalKnowledge* known = agent_.knowledge_.goals.find(goal.key);
    if (known != nullptr && known->literals == goal.literals) continue;  // known already, or its own
    const std::string kind = goal.key.category;
    agent_.knowledge_.goals.add(std::move(goal));
    if (std::find(announced_.begin(), announced_.end(), kind) != announced_.end()) continue;
    announced_.push_back(kind);
    const std::string robot = i < news->goal_robots.size() ? news->goal_robots[i] : std::string();
    auto heard = std::find_if(by_robot.begin(), by_robot.end(), [&](const auto& entry) { return entry.first == robot; });
    if (heard == by_robot.end()) heard = by_robot.insert(by_robot.end(), {robot, {}});
    heard->second.push_back(kind);
  }
  for (Rule& rule : news->rules) agent_.knowledge_.rules.add(*world().domain, std::move(rule));
  for (const auto& [robot, kinds] : by_robot) {
    const std::string sentence = language::news_sentence(robot, kinds);
    report_.news.push_back(sentence);
    say(sentence);
  }
}

}  // namespace apprentice
