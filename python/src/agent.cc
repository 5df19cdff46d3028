// apprentice.Agent: the task-learning agent, taught by any Python callable.
#include <atomic>

#include "bindings.h"
#include "face/apprentice.h"
#include "knowledge/learning.h"
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
    return question_class_(question.text, py::arg("kind") = to_string(question.kind),
                           py::arg("asked") = question_kind(question), py::arg("task") = question.task,
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

// What a run did, as a dict: the face's JSON report (to_json), with the
// world's facts at the end, and, after learning, the transcript.
py::dict report_dict(const SessionReport& report, const World& start) {
  py::dict out = py::module_::import("json").attr("loads")(to_json(report));
  // Without an intent there is nothing to measure against: 100%, as before.
  out["completion_rate"] = report.completion_rate;
  out["assertions_achieved"] = report.assertions_achieved;
  out["assertions_total"] = report.assertions_total;
  World end = start;
  end.state = report.end;
  out["facts"] = facts_of(end);
  out["summary"] = report.summary;
  return out;
}

class AgentHandle {
 public:
  AgentHandle(const py::object& scenario, const py::object& knowledge, const std::string& condition,
              const std::optional<std::string>& llm, const std::string& generalization, const AgentSpec& more)
      : scenario_(scenario_from(scenario)) {
    AgentSpec spec = more;
    spec.condition = condition;
    spec.generalization = generalization;
    spec.llm.backend = llm.value_or("");
    if (!knowledge.is_none())
      spec.knowledge = py::str(py::module_::import("os").attr("fspath")(knowledge)).cast<std::string>();
    Result<std::unique_ptr<AgentSession>> made;
    {
      py::gil_scoped_release release;  // checking the LLM server may take seconds
      made = make_agent_session(spec, *scenario_.scenario);
    }
    session_ = unwrap(std::move(made));
  }

  py::dict learn(py::object instructor) {
    if (!PyCallable_Check(instructor.ptr())) throw py::type_error("the instructor must be a callable (question: str) -> str");
    Busy busy(*this);
    PythonInstructor adapter(std::move(instructor));
    Result<SessionReport> report;
    {
      py::gil_scoped_release release;
      report = session_->learn(adapter);
    }
    adapter.rethrow_pending();
    SessionReport done = unwrap(std::move(report));
    py::dict out = report_dict(done, scenario_.scenario->world);
    out["transcript"] = done.transcript;
    return out;
  }

  py::dict perform(const py::object& scenario, const std::string& task) {
    Busy busy(*this);
    ScenarioHandle where = scenario.is_none() ? scenario_ : scenario_from(scenario);
    Result<SessionReport> report;
    {
      py::gil_scoped_release release;
      report = session_->perform(task, where.scenario.get());
    }
    return report_dict(unwrap(std::move(report)), where.scenario->world);
  }

  KnowledgeView knowledge() const { return view_of(session_->knowledge(), *scenario_.scenario->world.domain); }
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
  std::unique_ptr<AgentSession> session_;
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
      "generalization: 'full' (ours) or 'paper' (the paper's chunks).\n"
      "Keyword options, as the CLI's flags of the same names: use_rules, max_reprompts, goal_repair,\n"
      "offer_ungrounded, llm_model, llm_api_key, llm_timeout_ms, llm_connect_timeout_ms, llm_seed, llm_optional,\n"
      "llm_goal_responses; household (whose goal preferences and task structures the agent reads and writes in\n"
      "the store; the rules are shared by every household); robot (this robot's name, kept with what it learns and\n"
      "told to the other robots sharing the store; default: the host name).")
      .def(py::init([](const py::object& scenario, const py::object& knowledge, const std::string& condition,
                       const std::optional<std::string>& llm, const std::string& generalization,
                       const py::kwargs& options) {
             AgentSpec spec = default_agent_spec();
             apply_agent_options(options, spec);
             return std::make_unique<AgentHandle>(scenario, knowledge, condition, llm, generalization, spec);
           }),
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
