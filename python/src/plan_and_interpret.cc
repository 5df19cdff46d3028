// apprentice.plan(), apprentice.interpret() and apprentice.question_kinds:
// `apprentice plan` and `apprentice interpret` in Python, built by the
// face (face/apprentice.h) as the CLI's are, so that each gives what the
// CLI prints.
#include <limits>

#include "bindings.h"

namespace apprentice::python {

namespace {

py::object json_loads(const std::string& json) { return py::module_::import("json").attr("loads")(json); }

// `plan --json`'s keys, with `text` (what `plan` prints), `pddl` (what
// `plan --pddl` prints) and `why_not` (the CLI's line on stderr when no plan
// reaches the goal, else None).
py::dict plan(const py::object& scenario_or_path, const std::string& goal, const py::object& depth,
              const py::object& node_limit, const py::object& time_limit, const py::object& pruning) {
  ScenarioHandle scenario = scenario_from(scenario_or_path);
  PlanRequest request;
  request.goal = goal;
  if (!depth.is_none()) request.depth = static_cast<int>(whole_number(depth, "depth", 0, 64));
  if (!node_limit.is_none())
    request.node_limit = whole_number(node_limit, "node_limit", 1, std::numeric_limits<long>::max());
  if (!time_limit.is_none()) {
    if (!py::isinstance<py::int_>(time_limit) && !py::isinstance<py::float_>(time_limit))
      raise_error(Error{ErrorCode::kInvalidInput, "time_limit: " + std::string(py::repr(time_limit)) + " is not a number"});
    double seconds = time_limit.cast<double>();
    if (py::isinstance<py::bool_>(time_limit) || !(seconds > 0))
      raise_error(Error{ErrorCode::kInvalidInput,
                        "time_limit: " + std::string(py::repr(time_limit)) + " is not a number of seconds above 0"});
    request.time_limit_s = seconds;
  }
  request.pruning = flag(pruning, "pruning");
  Result<PlanFound> found;
  {
    py::gil_scoped_release release;
    found = apprentice::plan(*scenario.scenario, request);
  }
  PlanFound result = unwrap(std::move(found));
  py::dict out = json_loads(result.json);
  out["text"] = result.text;
  out["pddl"] = result.pddl;
  out["why_not"] = result.why_not.empty() ? py::object(py::none()) : py::object(py::str(result.why_not));
  return out;
}

std::optional<std::string> optional_text(const py::object& value, const char* name) {
  if (value.is_none()) return std::nullopt;
  return text(value, name);
}

// The keys of `interpret --json`, with `text` (what `interpret` prints) and
// `usable` (a reply) or `grounded` (a sentence); for a corpus, the report
// `interpret --corpus --json` prints.
py::dict interpret(const py::object& scenario_or_path, const py::object& sentence, const py::object& asked,
                   const py::object& object, const py::object& subtask, const py::object& recent,
                   const py::object& choices, const py::object& corpus) {
  ScenarioHandle scenario = scenario_from(scenario_or_path);
  if (sentence.is_none() == corpus.is_none())
    raise_error(Error{ErrorCode::kInvalidInput, "interpret takes either a sentence or corpus=FILE"});
  if (!corpus.is_none()) {
    std::filesystem::path path = py::str(py::module_::import("os").attr("fspath")(corpus)).cast<std::string>();
    Result<std::string> report;
    {
      py::gil_scoped_release release;
      report = interpret_corpus(*scenario.scenario, path, true);
    }
    return json_loads(unwrap(std::move(report)));
  }
  const std::string said = text(sentence, "sentence");
  const std::optional<std::string> about = optional_text(object, "object"), at = optional_text(subtask, "subtask");
  if (!asked.is_none()) {
    AskedQuestion question{text(asked, "asked"), about, at, optional_text(recent, "recent"), {}};
    if (!choices.is_none())
      for (const py::handle& choice : choices) question.choices.push_back(text(choice, "choices"));
    Result<ReplyReading> reading;
    {
      py::gil_scoped_release release;
      reading = interpret_reply(*scenario.scenario, said, question);
    }
    ReplyReading read = unwrap(std::move(reading));
    py::dict out = json_loads(read.json);
    out["usable"] = read.usable;
    out["text"] = read.text;
    return out;
  }
  Result<SentenceReading> reading;
  {
    py::gil_scoped_release release;
    reading = interpret_sentence(*scenario.scenario, said, about, at);
  }
  SentenceReading read = unwrap(std::move(reading));
  // As the CLI: a sentence the grammar does not cover is bad input.
  if (read.outside_grammar)
    raise_error(Error{ErrorCode::kInvalidInput, "the sentence is outside the grammar: " + read.detail});
  py::dict out = json_loads(read.json);
  out["grounded"] = read.grounded;
  out["text"] = read.text;
  return out;
}

}  // namespace

void bind_plan_and_interpret(py::module_& m) {
  m.def("plan", &plan, py::arg("scenario"), py::arg("goal"), py::kw_only(), py::arg("depth") = py::none(),
        py::arg("node_limit") = py::none(), py::arg("time_limit") = py::none(), py::arg("pruning") = true,
        "Plans from a scenario's state to a goal (PDDL, or 'intent' for the whole task), as `apprentice plan`: "
        "greedy best-first search, or iterative deepening to `depth`. Returns the keys of `plan --json` with "
        "`text` (the numbered sentences `plan` prints), `pddl` (what `plan --pddl` prints) and `why_not`.");
  m.def("interpret", &interpret, py::arg("scenario"), py::arg("sentence") = py::none(), py::kw_only(),
        py::arg("asked") = py::none(), py::arg("object") = py::none(), py::arg("subtask") = py::none(),
        py::arg("recent") = py::none(), py::arg("choices") = py::none(), py::arg("corpus") = py::none(),
        "What a sentence means in a scenario's world, as `apprentice interpret`: with `asked` (one of "
        "question_kinds) read as a teacher's reply at that kind of question; with `corpus`, a corpus of LLM goal "
        "statements grounded. Returns the keys of `interpret --json` with `text`, what `interpret` prints.");
  m.attr("question_kinds") = py::tuple(py::cast(question_kinds()));
}

}  // namespace apprentice::python
