// apprentice.experiment(): the paper's experiment, with the same results as
// `apprentice experiment --json` (one implementation: experiment/runner.h).
#include "bindings.h"
#include "experiment/runner.h"
#include "knowledge/store.h"
#include "face/llm_setup.h"

namespace apprentice::python {

namespace {

// The results as the JSON text `experiment --json` prints; the package's
// experiment() turns it into a list of dicts. The keyword options are the
// Agent's (apply_agent_options), as the CLI's flags of the same names.
std::string experiment_json(const py::object& scenario_path, const std::vector<std::string>& conditions,
                            const std::optional<std::string>& llm, const std::string& generalization,
                            const py::object& knowledge_in, const py::object& knowledge_out,
                            const py::object& transcript_dir, const py::kwargs& options) {
  ScenarioHandle scenario = scenario_from(scenario_path);
  AgentSpec spec = default_agent_spec();
  apply_agent_options(options, spec);
  ExperimentRequest request;
  if (!knowledge_in.is_none())
    request.options.knowledge_in =
        unwrap(load_knowledge_read_only(py::cast<std::string>(knowledge_in), *scenario.scenario->world.domain,
                                        spec.household));
  if (!knowledge_out.is_none()) request.options.knowledge_out = py::cast<std::string>(knowledge_out);
  request.options.household = spec.household;
  request.conditions = conditions;
  request.llm_spec = llm::resolve_llm_spec(llm.value_or(""));
  request.llm_options = llm_client_options(spec.llm);
  request.llm_optional = spec.llm.optional;
  request.options.generalization = unwrap(parse_generalization(generalization));
  request.options.use_rules = spec.use_rules;
  request.options.goal_repair = unwrap(parse_goal_repair(spec.goal_repair));
  request.options.max_reprompts = spec.max_reprompts;
  request.options.offer_ungrounded = spec.offer_ungrounded;
  request.options.goal_responses = spec.llm.goal_responses;
  request.options.prompts_dir = data_dir() / "prompts";
  std::optional<std::filesystem::path> transcripts;
  if (!transcript_dir.is_none()) transcripts = py::cast<std::string>(transcript_dir);
  if (transcripts)
    request.on_result = [&](const ConditionResult& result) -> Status {
      return write_transcript(*transcripts, result);
    };
  Result<ExperimentResults> run;
  {
    py::gil_scoped_release release;
    run = run_experiment(*scenario.scenario, request);
  }
  return results_json(unwrap(std::move(run)).results);
}

}  // namespace

void bind_experiment(py::module_& m) {
  m.def("_experiment_json", &experiment_json, py::arg("scenario_path"), py::arg("conditions"), py::arg("llm"),
        py::arg("generalization"), py::arg("knowledge_in"), py::arg("knowledge_out"), py::arg("transcript_dir"));
  m.def("condition_names", &paper_condition_names, "The paper's six conditions, in Table 3's order.");
  m.def(
      "paper_row",
      [](const std::string& condition) -> std::optional<py::dict> {
        auto row = paper_row(condition);
        if (!row) return std::nullopt;
        py::dict out;
        out["condition"] = std::string(row->condition);
        out["completion_rate"] = row->completion;
        out["relevance"] = row->relevance;
        out["instructions"] = row->instructions;
        out["words"] = row->words;
        out["yes_no"] = row->yes_no;
        return out;
      },
      py::arg("condition"),
      "The paper's Table 3 row for a condition, with the keys of experiment()'s results, or None.");
}

}  // namespace apprentice::python
