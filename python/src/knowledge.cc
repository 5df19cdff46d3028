// apprentice.Knowledge and apprentice.KnowledgeStore: learned goals, rules
// and task structure as Python objects, read-only.
#include "bindings.h"
#include "world/pddl.h"

namespace apprentice::python {

namespace {

std::string template_literal_text(const GoalTemplateLiteral& l) {
  std::string text = "(" + l.predicate;
  for (const GoalTemplateArgument& a : l.arguments) text += " " + (a.object_of_interest ? std::string("?o") : a.category);
  text += ")";
  return l.positive ? text : "(not " + text + ")";
}

// A store opened read-only: the file (or PostgreSQL database, by its URL)
// must exist and hold a store; nothing is ever written to it.
struct StoreView : KnowledgeView {
  std::string path;
  std::string household;
};

StoreView open_store(const py::object& path_like, const py::object& domain_path_like, const std::string& household) {
  py::object fspath = py::module_::import("os").attr("fspath");
  std::filesystem::path path = py::str(fspath(path_like)).cast<std::string>();
  std::filesystem::path domain_path = domain_path_like.is_none()
                                          ? data_dir() / "domains" / "kitchen.pddl"
                                          : std::filesystem::path(py::str(fspath(domain_path_like)).cast<std::string>());
  Result<StoreView> view = [&]() -> Result<StoreView> {
    py::gil_scoped_release release;
    std::error_code ec;
    const bool file = !is_postgres_location(path.string());
    if (file && !std::filesystem::exists(path, ec))
      return make_error(ErrorCode::kNotFound, path.string() + ": no such knowledge store");
    if (file && std::filesystem::file_size(path, ec) == 0)
      return make_error(ErrorCode::kFailedPrecondition, path.string() + " is empty, not a knowledge store");
    auto domain = read_domain_file(domain_path);
    if (!domain) return tl::unexpected(domain.error());
    auto store = KnowledgeStore::open(path, StoreAccess::kReadOnly, household);
    if (!store) return tl::unexpected(store.error());
    auto knowledge = store->load(*domain);
    if (!knowledge) return tl::unexpected(knowledge.error());
    StoreView out;
    static_cast<KnowledgeView&>(out) = view_of(*knowledge, *domain);
    out.path = store->location();
    out.household = store->household();
    return out;
  }();
  return unwrap(std::move(view));
}

std::string count_text(const KnowledgeView& k) {
  return std::to_string(k.tasks.size()) + " tasks, " + std::to_string(k.goals.size()) + " goals, " +
         std::to_string(k.rules.size()) + " rules";
}

}  // namespace

KnowledgeView view_of(const Knowledge& knowledge, const Domain& domain) {
  KnowledgeView out;
  for (const TaskKnowledge& t : knowledge.tasks) {
    TaskKnowledgeView task{t.name, {}};
    for (const LearnedSubtask& s : t.subtasks) task.subtasks.push_back({s.verb, s.relation, s.place_category});
    out.tasks.push_back(std::move(task));
  }
  for (const GoalKnowledge& g : knowledge.goals.all()) {
    GoalView goal{g.key.task, g.key.subtask, g.key.category, g.key.place, {}, format_goal_knowledge(g),
                  g.provenance.object, g.provenance.source};
    for (const GoalTemplateLiteral& l : g.literals) goal.literals.push_back(template_literal_text(l));
    out.goals.push_back(std::move(goal));
  }
  for (const Rule& r : knowledge.rules.rules())
    out.rules.push_back(RuleView{domain.actions.at(r.action).name, r.subtask, r.steps_to_goal, format_rule(domain, r),
                                 rule_signature(domain, r), r.provenance.object, r.provenance.source});
  return out;
}

void bind_knowledge(py::module_& m) {
  py::class_<GoalView>(m, "Goal",
                       "A learned goal: for an object of `category` at `place` in (task, subtask), the goal to reach. "
                       "'?o' in `literals` is the object; other places are named by category.")
      .def_readonly("task", &GoalView::task)
      .def_readonly("subtask", &GoalView::subtask)
      .def_readonly("category", &GoalView::category)
      .def_readonly("place", &GoalView::place)
      .def_readonly("literals", &GoalView::literals)
      .def_readonly("text", &GoalView::text, "In English-like If/Then form.")
      .def_readonly("learned_on", &GoalView::learned_on, "The object it was learned on.")
      .def_readonly("source", &GoalView::source, "Where it came from: the instructor's words, the LLM, ...")
      .def("__repr__", [](const GoalView& g) {
        std::string literals;
        for (const std::string& l : g.literals) literals += (literals.empty() ? "" : " ") + l;
        return "Goal(" + g.category + " on the " + g.place + " in " + g.subtask + ": " + literals + ")";
      });

  py::class_<RuleView>(m, "Rule", "A learned policy rule: in a matching goal and state, propose `action`.")
      .def_readonly("action", &RuleView::action)
      .def_readonly("subtask", &RuleView::subtask, "The subtask it is limited to, or None.")
      .def_readonly("steps_to_goal", &RuleView::steps_to_goal)
      .def_readonly("text", &RuleView::text, "The paper's If/Then form.")
      .def_readonly("signature", &RuleView::signature, "One line: action <- goal{...} state{...} steps=N.")
      .def_readonly("learned_on", &RuleView::learned_on)
      .def_readonly("source", &RuleView::source)
      .def("__repr__", [](const RuleView& r) { return "Rule(" + r.signature + ")"; });

  py::class_<SubtaskKnowledgeView>(m, "LearnedSubtask",
                                   "A step of a learned task: while an object is `relation` a `place`, `verb` it.")
      .def_readonly("verb", &SubtaskKnowledgeView::verb)
      .def_readonly("relation", &SubtaskKnowledgeView::relation)
      .def_readonly("place", &SubtaskKnowledgeView::place)
      .def("__repr__", [](const SubtaskKnowledgeView& s) {
        return "LearnedSubtask('" + s.verb + "', " + s.relation + " the " + s.place + ")";
      });

  py::class_<TaskKnowledgeView>(m, "TaskKnowledge", "A learned task: its name and subtasks, places by category.")
      .def_readonly("name", &TaskKnowledgeView::name)
      .def_readonly("subtasks", &TaskKnowledgeView::subtasks)
      .def("__repr__", [](const TaskKnowledgeView& t) {
        return "TaskKnowledge('" + t.name + "', " + std::to_string(t.subtasks.size()) + " subtasks)";
      });

  py::class_<KnowledgeView>(m, "Knowledge", "What an agent knows: tasks, goals and rules (a copy, read-only).")
      .def_readonly("tasks", &KnowledgeView::tasks)
      .def_readonly("goals", &KnowledgeView::goals)
      .def_readonly("rules", &KnowledgeView::rules)
      .def("__repr__", [](const KnowledgeView& k) { return "<Knowledge: " + count_text(k) + ">"; });

  py::class_<StoreView, KnowledgeView>(
      m, "KnowledgeStore",
      "A knowledge store (an SQLite file or a postgresql:// URL) written by `apprentice teach` or an Agent, read "
      "into memory; never written. `domain` is the PDDL domain its rules use (default: the shipped kitchen); "
      "`household` whose goals and tasks are read (the rules are shared by every household).")
      .def(py::init(&open_store), py::arg("path"), py::arg("domain") = py::none(), py::arg("household") = kDefaultHousehold,
           "Raises apprentice.Error: 'not found' for a missing file, 'failed precondition' for a file that is not "
           "a store of this version, 'data loss' for an unreadable one.")
      .def_readonly("path", &StoreView::path)
      .def_readonly("household", &StoreView::household)
      .def("__repr__", [](const StoreView& k) { return "<KnowledgeStore " + k.path + ": " + count_text(k) + ">"; });
}

}  // namespace apprentice::python
