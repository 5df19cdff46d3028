// apprentice.Agent: the task-learning agent, taught by any Python callable.
#include <atomic>

#include "agent/agent.h"
#include "bindings.h"
#include "experiment/experiment.h"
#include "llm/factory.h"
#include "world/action.h"
#include "world/goal.h"

namespace apprentice::python {

namespace {

// The Instructor interface over a Python callable (question: str) -> str;
// the question is an apprentice.Question, a str that also says what it is
// about.
// An exception the callable raises ends the learning run (as the instructor
// leaving would, so that what was learned is kept) and is kept here, to be
// raised again, traceback and all, once the run has returned. Returning
// None means the instructor has gone.
class PythonInstructor final : public Instructor {
 public:
  // Needs the GIL.
  explicit PythonInstructor(py::object callback)
      : callback_(std::move(callback)), question_class_(py::module_::import("apprentice").attr("Question")) {}
  ~PythonInstructor() override {
    py::gil_scoped_acquire gil;
    pending_.reset();
    callback_ = py::object();
    question_class_ = py::object();
  }

  Result<std::string> answer(const Question& question, const World& world) override {
    py::gil_scoped_acquire gil;
    if (pending_) return cancelled();
    try {
      py::object reply = callback_(python_question(question, world));
      if (reply.is_none()) return make_error(ErrorCode::kCancelled, "the instructor returned None");
      if (!py::isinstance<py::str>(reply)) {
        std::string type = py::str(py::type::handle_of(reply).attr("__name__"));
        PyErr_SetString(PyExc_TypeError, ("the instructor must return a str (or None to stop), not " + type).c_str());
        throw py::error_already_set();
      }
      return reply.cast<std::string>();
    } catch (py::error_already_set& e) {
      pending_.emplace(std::move(e));
      return cancelled();
    }
  }

  void hear(std::string_view statement) override {
    py::gil_scoped_acquire gil;
    if (pending_ || !py::hasattr(callback_, "hear")) return;
    try {
      callback_.attr("hear")(std::string(statement));
    } catch (py::error_already_set& e) {
      pending_.emplace(std::move(e));
    }
  }

  // Raises the callback's exception in the caller, if there was one. Needs
  // the GIL.
  void rethrow_pending() {
    if (!pending_) return;
    py::error_already_set error = std::move(*pending_);
    pending_.reset();
    throw error;
  }

 private:
  // apprentice.Question: the text, with what it is about.
  py::object python_question(const Question& question, const World& world) const {
    py::object object = py::none(), category = py::none(), place = py::none(), goal = py::none(),
               action = py::none();
    if (question.object) {
      object = py::str(world.universe->name(*question.object));
      category = py::str(world.universe->info(*question.object).category);
      if (auto where = place_of(world, *question.object)) place = py::str(*where);
    }
    if (question.goal) goal = py::str(format_goal(*world.domain, *world.universe, *question.goal));
    if (question.action) action = py::str(format_action(*world.domain, *world.universe, *question.action));
    return question_class_(question.text, py::arg("kind") = to_string(question.kind), py::arg("task") = question.task,
                           py::arg("subtask") = question.subtask, py::arg("object") = object,
                           py::arg("category") = category, py::arg("place") = place, py::arg("goal") = goal,
                           py::arg("action") = action);
  }

  static tl::unexpected<Error> cancelled() {
    return make_error(ErrorCode::kCancelled, "the instructor raised an exception");
  }

  py::object callback_;
  py::object question_class_;
  std::optional<py::error_already_set> pending_;
};

py::list object_reports(const std::vector<ObjectReport>& objects) {
  py::list out;
  for (const ObjectReport& o : objects)
    out.append(py::dict(py::arg("object") = o.object, py::arg("subtask") = o.subtask,
                        py::arg("goal_source") = o.goal_source, py::arg("goal") = o.goal,
                        py::arg("achieved") = o.achieved, py::arg("note") = o.note));
  return out;
}

// What a run did, as a dict: the report, and completion against the
// scenario's intent.
py::dict report_dict(const Scenario& scenario, const Simulator& simulator, const AgentReport& report) {
  int achieved = count_achieved_assertions(scenario, simulator.state());
  int total = static_cast<int>(scenario.goal_assertions().size());
  py::dict out;
  out["task_finished"] = report.task_finished;
  out["completion_rate"] = completion_percent(achieved, total);
  out["assertions_achieved"] = achieved;
  out["assertions_total"] = total;
  out["objects"] = object_reports(report.objects);
  out["actions_executed"] = report.actions_executed;
  out["rule_actions"] = report.rule_actions;
  out["search_nodes"] = report.search_nodes;
  out["goals_learned"] = report.goals_learned;
  out["rules_learned"] = report.rules_learned;
  out["help_needed"] = report.help_needed;
  out["facts"] = facts_of(simulator.world());
  return out;
}

class AgentHandle {
 public:
  AgentHandle(const py::object& scenario, const py::object& knowledge, const std::string& condition_name,
              const std::optional<std::string>& llm_spec, const std::string& generalization)
      : scenario_(scenario_from(scenario)) {
    Condition condition = unwrap(parse_condition(condition_name));
    AgentOptions options;
    options.condition = condition;
    options.generalization = unwrap(parse_generalization(generalization));
    Knowledge known;
    if (!knowledge.is_none()) {
      std::filesystem::path path = py::str(py::module_::import("os").attr("fspath")(knowledge)).cast<std::string>();
      store_.emplace(unwrap(KnowledgeStore::open(path)));
      known = unwrap(store_->load(*scenario_.scenario->world.domain));
    }
    if (condition.llm) {
      auto spec = llm::resolve_llm_spec(llm_spec.value_or(""));
      if (!spec)
        raise_error(Error{ErrorCode::kInvalidInput, "condition " + condition.name +
                                                         " needs an LLM: pass llm='openai:http://HOST:PORT/v1' "
                                                         "(or another backend spec), or set APPRENTICE_LLM"});
      auto client = unwrap(llm::make_llm_client(*spec, llm::LlmOptions{}));
      auto templates = unwrap(llm::PromptTemplates::load(data_dir() / "prompts"));
      advisor_ = std::make_unique<LlmAdvisor>(std::move(client), std::move(templates));
    }
    agent_ = std::make_unique<TaskLearningAgent>(options, std::move(known), Understanding(),
                                                 store_ ? &*store_ : nullptr, advisor_.get());
  }

  py::dict learn(py::object instructor) {
    if (!PyCallable_Check(instructor.ptr())) throw py::type_error("the instructor must be a callable (question: str) -> str");
    Busy busy(*this);
    PythonInstructor adapter(std::move(instructor));
    Simulator simulator(scenario_.scenario->world);
    Dialogue dialogue(adapter);
    Result<AgentReport> report;
    {
      py::gil_scoped_release release;
      report = agent_->learn(simulator, dialogue);
    }
    adapter.rethrow_pending();
    bool stopped = !report && report.error().code == ErrorCode::kCancelled;
    if (!report && !stopped) raise_error(report.error());
    py::dict out = report_dict(*scenario_.scenario, simulator, report ? *report : AgentReport{});
    if (stopped) out["stopped"] = report.error().message;
    const DialogueCounts& counts = dialogue.counts();
    out["instructions"] = counts.instructions;
    out["words"] = counts.words;
    out["yes_no"] = counts.yes_no;
    out["yes"] = counts.yes;
    if (advisor_) out["llm_calls"] = advisor_->totals().calls;
    else out["llm_calls"] = 0;
    out["transcript"] = dialogue.transcript_text();
    return out;
  }

  py::dict perform(const py::object& scenario, const std::string& task) {
    Busy busy(*this);
    ScenarioHandle where = scenario.is_none() ? scenario_ : scenario_from(scenario);
    Simulator simulator(where.scenario->world);
    Result<AgentReport> report;
    {
      py::gil_scoped_release release;
      report = agent_->perform(simulator, task);
    }
    return report_dict(*where.scenario, simulator, unwrap(std::move(report)));
  }

  KnowledgeView knowledge() const { return view_of(agent_->knowledge(), *scenario_.scenario->world.domain); }
  const ScenarioHandle& scenario() const { return scenario_; }

 private:
  // One run at a time: the GIL is released while the agent works, so
  // another Python thread could otherwise reach the same agent.
  class Busy {
   public:
    explicit Busy(AgentHandle& agent) : agent_(agent) {
      if (agent_.busy_.exchange(true)) throw std::runtime_error("the agent is already learning or performing");
    }
    ~Busy() { agent_.busy_ = false; }

   private:
    AgentHandle& agent_;
  };

  ScenarioHandle scenario_;
  std::optional<KnowledgeStore> store_;
  std::unique_ptr<LlmAdvisor> advisor_;
  std::unique_ptr<TaskLearningAgent> agent_;
  std::atomic<bool> busy_ = false;
};

}  // namespace

void bind_agent(py::module_& m) {
  py::class_<AgentHandle>(
      m, "Agent",
      "The task-learning agent in a scenario's world.\n\n"
      "knowledge: a knowledge store (SQLite) to start from and to keep what is learned in; None keeps nothing.\n"
      "condition: the knowledge sources besides the instructor, e.g. 'inst+search4', 'instruction', 'inst+llm'.\n"
      "llm: an LLM backend spec ('openai:http://127.0.0.1:8080/v1', 'replay:FILE', 'corpus:FILE', ...) for the\n"
      "LLM conditions; None uses $APPRENTICE_LLM.\n"
      "generalization: 'full' (ours) or 'paper' (the paper's chunks).")
      .def(py::init<const py::object&, const py::object&, const std::string&, const std::optional<std::string>&,
                    const std::string&>(),
           py::arg("scenario"), py::arg("knowledge") = py::none(), py::arg("condition") = "inst+search4",
           py::arg("llm") = py::none(), py::arg("generalization") = "full")
      .def("learn", &AgentHandle::learn, py::arg("instructor"),
           "Learns and performs the task, asking `instructor`, a callable (question: str) -> str, whenever it needs\n"
           "help; the question is an apprentice.Question, a str that also has kind, object, category, goal, .... If the callable has a method hear(statement), it hears what the agent says without asking.\n"
           "Returning None stops the lesson; what was learned is kept. An exception the callable raises stops it\n"
           "too and reaches the caller unchanged. Returns a dict: instructions, words, yes_no, completion_rate,\n"
           "objects, transcript, ...")
      .def("perform", &AgentHandle::perform, py::arg("scenario") = py::none(), py::arg("task") = "",
           "Performs a learned task with learned knowledge alone (no instructor, search or LLM) in a fresh copy of\n"
           "`scenario` (default: the agent's). Returns a dict with completion_rate and help_needed.")
      .def_property_readonly("knowledge", &AgentHandle::knowledge, "What the agent knows now (a copy).")
      .def_property_readonly("scenario", &AgentHandle::scenario);
}

}  // namespace apprentice::python
