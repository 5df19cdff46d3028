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

#include <apprentice/face/apprentice.h>

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
        return words::task_name(scenario_.task.name);
      case QuestionKind::kTaskStep:
        return next_task_step(world);
      case QuestionKind::kSubtaskStep: {
        // About an object: its goal. About the subtask alone: it is done.
        if (!question.object) return words::done();
        auto goal = scenario_.intended_goal(question.subtask, *question.object);
        if (!goal || goal->satisfied_by(world.state)) return words::done();
        return words::goal(world, *question.object, *goal);
      }
      default:
        // With search (inst+search4) the agent finds the actions itself and
        // asks nothing else; a fuller teacher would answer here too.
        return words::answer(false);
    }
  }

  void hear(std::string_view statement) override { std::printf("  agent: %.*s\n", int(statement.size()), statement.data()); }

 private:
  // "Repeat the following tasks while an object is on the table.", "Clear
  // an object that is on the table.", then "Repeat." after the first
  // object; then the next subtask; and "You are done." at the end.
  std::string next_task_step(const World& world) {
    if (subtask_ >= scenario_.task.subtasks.size()) return words::done();
    const Subtask& subtask = scenario_.task.subtasks[subtask_];
    switch (step_++) {
      case 0: return words::repeat_while(world, subtask.places);
      case 1: return words::subtask(subtask.verb, world, subtask.places);
      default:
        ++subtask_;
        step_ = 0;
        return words::repeat();
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
  // the actions. No knowledge store: nothing is kept on disk. The condition
  // uses no LLM.
  AgentSpec spec = default_agent_spec();
  spec.condition = "inst+search4";
  Result<std::unique_ptr<AgentSession>> agent = make_agent_session(spec, *scenario);
  if (!agent) {
    std::fprintf(stderr, "teach_kitchen: %s\n", agent.error().describe().c_str());
    return 2;
  }

  KitchenTeacher teacher(*scenario);
  Result<SessionReport> learned = (*agent)->learn(teacher);
  if (!learned) {
    std::fprintf(stderr, "teach_kitchen: %s\n", learned.error().describe().c_str());
    return 1;
  }
  std::printf("Learned %s: %d of %d goal assertions hold; %d instructions, %d words; %d goals and %d rules learned.\n",
              scenario->task.name.c_str(), learned->assertions_achieved, learned->assertions_total,
              learned->counts.instructions, learned->counts.words, learned->agent.goals_learned,
              learned->agent.rules_learned);

  // Again, from the start, with learned knowledge alone.
  Result<SessionReport> performed = (*agent)->perform(scenario->task.name);
  if (!performed) {
    std::fprintf(stderr, "teach_kitchen: %s\n", performed.error().describe().c_str());
    return 1;
  }
  std::printf("Performed alone: %d of %d goal assertions hold; %zu points needed help.\n",
              performed->assertions_achieved, performed->assertions_total, performed->agent.help_needed.size());
  std::printf("As JSON: %s\n", to_json(*performed).c_str());
  return performed->agent.help_needed.empty() ? 0 : 1;
}
