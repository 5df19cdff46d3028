// apprentice.Knowledge and apprentice.KnowledgeStore: learned goals, rules
// and task structure as Python objects, read-only.
#include "agent/class_rule_knowledge.h"
#include "agent/goal_proposals.h"
#include "agent/concept_source.h"
#include "agent/goal_proposals.h"
#include "agent/understanding.h"
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

ClassRuleView class_rule_view(const ClassRule& rule) {
  return ClassRuleView{say_class_rule(rule),
                       rule_subject(rule),
                       rule_destination(rule),
                       rule.evidence,
                       rule.exceptions,
                       std::string(rule_source_name(rule.source)),
                       rule.said,
                       rule.confidence,
                       rule.scope.task};
}

std::filesystem::path domain_path_of(const py::object& domain_path_like) {
  py::object fspath = py::module_::import("os").attr("fspath");
  return domain_path_like.is_none() ? data_dir() / "domains" / "kitchen.pddl"
                                    : std::filesystem::path(py::str(fspath(domain_path_like)).cast<std::string>());
}

// apprentice.forget_rule: the one call of this module that writes a store.
std::vector<ClassRuleView> forget_rule(const py::object& path_like, const std::string& what,
                                       const py::object& domain_path_like, const std::string& household) {
  const std::string path = py::str(py::module_::import("os").attr("fspath")(path_like)).cast<std::string>();
  const std::filesystem::path domain_path = domain_path_of(domain_path_like);
  Result<std::vector<ClassRuleView>> forgotten = [&]() -> Result<std::vector<ClassRuleView>> {
    py::gil_scoped_release release;
    if (!is_postgres_location(path) && !std::filesystem::exists(path))
      return make_error(ErrorCode::kNotFound, path + ": no such knowledge store");
    auto domain = read_domain_file(domain_path);
    if (!domain) return tl::unexpected(domain.error());
    Understanding understanding;
    LexicalConcepts concepts(understanding.lexicon(), understanding.vectors());
    auto rules = forget_rules_named(path, household, *domain, what, concepts);
    if (!rules) return tl::unexpected(rules.error());
    std::vector<ClassRuleView> out;
    for (const ClassRule& rule : *rules) out.push_back(class_rule_view(rule));
    return out;
  }();
  return unwrap(std::move(forgotten));
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
  std::filesystem::path domain_path = domain_path_of(domain_path_like);
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
    // The class rules as `apprentice knowledge` lists them: induced anew
    // from the goals (WordNet and the word vectors), and a person's.
    Understanding understanding;
    LexicalConcepts concepts(understanding.lexicon(), understanding.vectors());
    static_cast<KnowledgeView&>(out) = view_of(*knowledge, *domain, &concepts);
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

KnowledgeView view_of(const Knowledge& knowledge, const Domain& domain, const ConceptSource* concepts) {
  KnowledgeView out;
  if (concepts != nullptr) {
    for (const ClassRule& rule : class_rules_in_use(knowledge, *concepts)) out.class_rules.push_back(class_rule_view(rule));
  } else {
    for (const ClassRule& rule : knowledge.class_rules.all())
      if (!knowledge.forgot(rule)) out.class_rules.push_back(class_rule_view(rule));
  }
  for (const ClassRule& rule : knowledge.forgotten_rules.all()) out.forgotten_rules.push_back(class_rule_view(rule));
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

  py::class_<ClassRuleView>(m, "ClassRule",
                            "A rule about a class of things: `subject` goes `destination`, from `evidence` (the kinds "
                            "it was induced from or confirmed on), said by `source` ('induced', 'person', 'llm').")
      .def_readonly("text", &ClassRuleView::text, "In English, as `apprentice knowledge` says it.")
      .def_readonly("subject", &ClassRuleView::subject, "What it is about: 'edible fruit', 'other clothes'.")
      .def_readonly("destination", &ClassRuleView::destination, "Where it sends things: 'on the coffee table'.")
      .def_readonly("evidence", &ClassRuleView::evidence)
      .def_readonly("exceptions", &ClassRuleView::exceptions, "Kinds of the class that go elsewhere.")
      .def_readonly("source", &ClassRuleView::source)
      .def_readonly("said", &ClassRuleView::said, "The sentence it was read from; '' when induced.")
      .def_readonly("confidence", &ClassRuleView::confidence, "How sure its source is, 0 to 1.")
      .def_readonly("task", &ClassRuleView::task, "The task it holds for; '' for any.")
      .def("__repr__", [](const ClassRuleView& r) {
        return "ClassRule(" + r.subject + " " + r.destination + ", " + r.source + ")";
      });

  m.def("forget_rule", &forget_rule, py::arg("store"), py::arg("what"), py::arg("domain") = py::none(),
        py::arg("household") = kDefaultHousehold,
        "Forgets, for good, the class rule `what` names in the knowledge store at `store` (what it is about, "
        "optionally with where it sends things: 'fruit', 'fruit on the coffee table'), as `apprentice knowledge "
        "forget` does: the store keeps it as forgotten, and the agent no longer uses it. Returns the rules "
        "forgotten. Raises apprentice.Error: 'invalid input' when `what` names no rule, or rules that differ.");

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
      .def_readonly("class_rules", &KnowledgeView::class_rules,
                    "The rules about classes of things in use, with their evidence (apprentice.ClassRule).")
      .def_readonly("forgotten_rules", &KnowledgeView::forgotten_rules, "The class rules forgotten, never used.")
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
