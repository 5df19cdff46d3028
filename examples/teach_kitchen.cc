// A minimal program on the installed apprentice package: it loads a
// scenario, teaches an agent with an instructor class of its own, and then
// lets the agent do the task again with what it learned alone.
//
//   teach_kitchen [SCENARIO]     (default: the installed tidy-kitchen.yaml)
//
// Build it against an installation (see CMakeLists.txt beside it):
//   cmake --install build --prefix $HOME/.local
//   cmake -S examples -B build-example -DCMAKE_PREFIX_PATH=$HOME/.local && cmake --build build-example
#include <cstdio>
#include <string>

#include <apprentice/agent/agent.h>
#include <apprentice/experiment/experiment.h>
#include <apprentice/instructor/dialogue.h>
#include <apprentice/instructor/instructor.h>
#include <apprentice/language/generation.h>
#include <apprentice/world/scenario.h>
#include <apprentice/world/simulator.h>

namespace {

using namespace apprentice;

// An instructor that knows what the scenario's author wants (its intent)
// and says it in the words of the paper's instructor script. A person, a
// scripted teacher or an LLM would implement the same two functions.
class KitchenTeacher final : public Instructor {
 public:
  explicit KitchenTeacher(const Scenario& scenario) : scenario_(scenario) {}

  Result<std::string> answer(const Question& question, const World& world) override {
    switch (question.kind) {
      case QuestionKind::kTaskName:
        return language::say_task_name(scenario_.task.name);
      case QuestionKind::kTaskStep:
        return next_task_step(world);
      case QuestionKind::kSubtaskStep: {
        // About an object: its goal. About the subtask alone: it is done.
        if (!question.object) return language::say_done();
        auto goal = scenario_.intended_goal(question.subtask, *question.object);
        if (!goal || goal->satisfied_by(world.state)) return language::say_done();
        return language::describe_goal_instruction(world, *question.object, *goal);
      }
      default:
        // With search (inst+search4) the agent finds the actions itself and
        // asks nothing else; a fuller teacher would answer here too.
        return language::say_answer(false);
    }
  }

  void hear(std::string_view statement) override { std::printf("  agent: %.*s\n", int(statement.size()), statement.data()); }

 private:
  // "Repeat the following tasks while an object is on the table.", "Clear
  // an object that is on the table.", then "Repeat." after the first
  // object; then the next subtask; and "You are done." at the end.
  std::string next_task_step(const World& world) {
    if (subtask_ >= scenario_.task.subtasks.size()) return language::say_done();
    const Subtask& subtask = scenario_.task.subtasks[subtask_];
    switch (step_++) {
      case 0: return language::say_repeat_while(world, subtask.places);
      case 1: return language::say_subtask(subtask.verb, world, subtask.places);
      default:
        ++subtask_;
        step_ = 0;
        return language::say_repeat();
    }
  }

  const Scenario& scenario_;
  std::size_t subtask_ = 0;
  int step_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  std::string path = argc > 1 ? argv[1] : APPRENTICE_DATA_DIR "/scenarios/tidy-kitchen.yaml";
  Result<Scenario> scenario = load_scenario(path);
  if (!scenario) {
    std::fprintf(stderr, "teach_kitchen: %s\n", scenario.error().describe().c_str());
    return 2;
  }

  // inst+search4: the teacher gives the task and the goals; search finds
  // the actions. No knowledge store (nullptr): nothing is kept on disk. No
  // LLM (nullptr): the condition does not use one.
  AgentOptions options;
  options.condition = *parse_condition("inst+search4");
  TaskLearningAgent agent(options, Knowledge{}, Understanding(), nullptr, nullptr);

  Simulator simulator(scenario->world);
  KitchenTeacher teacher(*scenario);
  Dialogue dialogue(teacher);
  Result<AgentReport> learned = agent.learn(simulator, dialogue);
  if (!learned) {
    std::fprintf(stderr, "teach_kitchen: %s\n", learned.error().describe().c_str());
    return 1;
  }
  std::printf("Learned %s: %d of %zu goal assertions hold; %d instructions, %d words; %d goals and %d rules learned.\n",
              scenario->task.name.c_str(), count_achieved_assertions(*scenario, simulator.state()),
              scenario->goal_assertions().size(), dialogue.counts().instructions, dialogue.counts().words,
              learned->goals_learned, learned->rules_learned);

  // Again, from the start, with learned knowledge alone.
  Simulator again(scenario->world);
  Result<AgentReport> performed = agent.perform(again, scenario->task.name);
  if (!performed) {
    std::fprintf(stderr, "teach_kitchen: %s\n", performed.error().describe().c_str());
    return 1;
  }
  std::printf("Performed alone: %d of %zu goal assertions hold; %zu points needed help.\n",
              count_achieved_assertions(*scenario, again.state()), scenario->goal_assertions().size(),
              performed->help_needed.size());
  return performed->help_needed.empty() ? 0 : 1;
}
