// apprentice.experiment(): the paper's experiment, with the same results as
// `apprentice experiment --json` (one implementation: experiment/runner.h).
#include "bindings.h"
#include "experiment/runner.h"
#include "knowledge/store.h"

namespace apprentice::python {

namespace {

// The results as the JSON text `experiment --json` prints; the package's
// experiment() turns it into a list of dicts.
std::string experiment_json(const py::object& scenario_path, const std::vector<std::string>& conditions,
                            const std::optional<std::string>& llm, const std::string& generalization,
                            const py::object& knowledge_in, bool use_rules) {
  ScenarioHandle scenario = scenario_from(scenario_path);
  ExperimentRequest request;
  if (!knowledge_in.is_none())
    request.options.knowledge_in =
        unwrap(load_knowledge_read_only(py::cast<std::string>(knowledge_in), *scenario.scenario->world.domain));
  request.conditions = conditions;
  request.llm_spec = llm::resolve_llm_spec(llm.value_or(""));
  request.options.generalization = unwrap(parse_generalization(generalization));
  request.options.use_rules = use_rules;
  request.options.prompts_dir = data_dir() / "prompts";
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
        py::arg("generalization"), py::arg("knowledge_in"), py::arg("use_rules"));
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
