// What other robots learned while this agent runs: the store's news
// (KnowledgeStore::news), taken into the agent's knowledge before each
// object and said once per kind.
#include <algorithm>

#include "agent/agent.h"
#include "agent/session.h"
#include "language/generation.h"

namespace apprentice {

namespace {

// "Another robot just learned where the ketchup goes." or "... where the
// ketchup and the paper plate go."
std::string news_sentence(const std::vector<std::string>& kinds) {
  std::string things;
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    if (i > 0) things += i + 1 == kinds.size() ? (kinds.size() > 2 ? ", and " : " and ") : ", ";
    things += "the " + language::spoken_category(kinds[i]);
  }
  return "Another robot just learned where " + things + (kinds.size() == 1 ? " goes." : " go.");
}

}  // namespace

void TaskLearningAgent::Session::take_news() {
  KnowledgeStore* store = agent_.watched_;
  if (store == nullptr) return;
  auto news = store->news(*world().domain);
  // A look that fails (the server is restarting) is not the lesson's
  // failure: the agent goes on with what it knows and looks again at the
  // next object.
  if (!news || news->empty()) return;
  std::vector<std::string> kinds;
  for (GoalKnowledge& goal : news->goals) {
    const GoalKnowledge* known = agent_.knowledge_.goals.find(goal.key);
    if (known != nullptr && known->literals == goal.literals) continue;  // known already, or its own
    const std::string kind = goal.key.category;
    agent_.knowledge_.goals.add(std::move(goal));
    if (std::find(announced_.begin(), announced_.end(), kind) != announced_.end()) continue;
    if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) kinds.push_back(kind);
  }
  for (Rule& rule : news->rules) agent_.knowledge_.rules.add(*world().domain, std::move(rule));
  if (kinds.empty()) return;
  announced_.insert(announced_.end(), kinds.begin(), kinds.end());
  const std::string sentence = news_sentence(kinds);
  report_.news.push_back(sentence);
  say(sentence);
}

}  // namespace apprentice
