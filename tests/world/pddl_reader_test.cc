// The PDDL reader: a table of broken domains, each with the exact
// "file:line:column: expected ..." message it must produce; the features
// the kitchen needs (typing, negative preconditions, equality); and the
// problem reader.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "world/action.h"
#include "world/pddl.h"
#include "world_fixtures.h"

namespace apprentice {
namespace {

using ::testing::HasSubstr;

// A small valid domain, one line per entry, so cases can edit single lines
// and say exactly where the error must point.
std::vector<std::string> base_domain() {
  return {
      "(define (domain d)",                                            // 1
      "  (:requirements :strips :typing)",                             // 2
      "  (:types item place)",                                         // 3
      "  (:predicates (at ?o - item ?p - place) (free ?p - place))",  // 4
      "  (:action move",                                               // 5
      "    :parameters (?o - item ?a - place ?b - place)",            // 6
      "    :precondition (and (at ?o ?a) (free ?b))",                 // 7
      "    :effect (and (at ?o ?b) (not (at ?o ?a)))))",              // 8
  };
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& l : lines) out += l + "\n";
  return out;
}

// "d.pddl:LINE:COLUMN" where COLUMN is that of the `occurrence`-th `token`
// on the 1-based `line`.
std::string where(const std::vector<std::string>& lines, std::size_t line, std::string_view token,
                  int occurrence = 1) {
  const std::string text = line <= lines.size() ? lines[line - 1] : std::string();
  std::size_t at = std::string::npos;
  for (int i = 0; i < occurrence; ++i) at = text.find(token, at == std::string::npos ? 0 : at + 1);
  EXPECT_NE(at, std::string::npos) << "token " << token << " not on line " << line;
  return "d.pddl:" + std::to_string(line) + ":" + std::to_string(at + 1);
}

TEST(PddlReader, BaseDomainParses) {
  auto domain = parse_domain(join_lines(base_domain()), "d.pddl");
  ASSERT_TRUE(domain.has_value()) << domain.error().describe();
  EXPECT_EQ(domain->name, "d");
  EXPECT_EQ(domain->requirements, (std::vector<std::string>{"strips", "typing"}));
  ASSERT_EQ(domain->actions.size(), 1u);
  EXPECT_EQ(domain->actions[0].parameters.size(), 3u);
  EXPECT_EQ(domain->actions[0].preconditions.size(), 2u);
  EXPECT_EQ(domain->actions[0].add_effects.size(), 1u);
  EXPECT_EQ(domain->actions[0].delete_effects.size(), 1u);
  EXPECT_FALSE(domain->is_static(*domain->find_predicate("at")));
  EXPECT_TRUE(domain->is_static(*domain->find_predicate("free")));
}

struct ErrorCase {
  const char* name;
  // Replaces line `line` (1-based) with `text`; line 0 means no edit.
  std::size_t line;
  const char* text;
  // Where the error must point: the line and a token on it.
  std::size_t error_line;
  const char* error_token;
  int occurrence;
  const char* message;
};

class PddlReaderErrors : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(PddlReaderErrors, NamesFileLineColumnAndWhatWasExpected) {
  const ErrorCase& c = GetParam();
  std::vector<std::string> lines = base_domain();
  if (c.line > 0) lines.at(c.line - 1) = c.text;
  auto domain = parse_domain(join_lines(lines), "d.pddl");
  ASSERT_FALSE(domain.has_value()) << c.name;
  EXPECT_EQ(domain.error().code, ErrorCode::kInvalidInput);
  EXPECT_EQ(domain.error().message, where(lines, c.error_line, c.error_token, c.occurrence) + ": " + c.message);
}

const ErrorCase kErrorCases[] = {
    {"missing_paren", 8, "    :effect (and (at ?o ?b) (not (at ?o ?a))))", 9, "", 1,
     "expected ')' to close the list opened at line 1:1"},
    {"unknown_requirement", 2, "  (:requirements :strips :typing :fluents)", 2, ":fluents", 1,
     "expected :strips, :typing, :negative-preconditions or :equality; :fluents is not supported"},
    {"undeclared_predicate", 7, "    :precondition (and (at ?o ?a) (near ?o ?b))", 7, "near", 1,
     "expected a declared predicate, not near"},
    {"wrong_arity", 7, "    :precondition (and (at ?o) (free ?b))", 7, "(at", 1, "expected 2 arguments for at"},
    {"wrong_arity_in_effect", 8, "    :effect (and (at ?o ?a ?b) (not (at ?o ?a)))))", 8, "(at", 1,
     "expected 2 arguments for at"},
    {"undeclared_type_in_predicate", 4, "  (:predicates (at ?o - thing ?p - place) (free ?p - place))", 4, "thing", 1,
     "expected a declared type, not thing"},
    {"undeclared_type_in_parameters", 6, "    :parameters (?o - item ?a - place ?b - room)", 6, "room", 1,
     "expected a declared type, not room"},
    {"negative_precondition_needs_requirement", 7, "    :precondition (and (at ?o ?a) (not (free ?b)))", 7,
     "(not", 1, "(not ...) in a precondition needs :negative-preconditions in :requirements"},
    {"equality_needs_requirement", 7, "    :precondition (and (at ?o ?a) (not (= ?a ?b)))", 7, "(=", 1,
     "(= ...) needs :equality in :requirements"},
    {"disjunction_unsupported", 7, "    :precondition (or (at ?o ?a) (free ?b))", 7, "(or", 1,
     "expected a literal; or is not supported in STRIPS"},
    {"variable_not_a_parameter", 7, "    :precondition (and (at ?x ?a) (free ?b))", 7, "?x", 1,
     "expected a parameter of the action; ?x is not one"},
    {"constant_argument", 7, "    :precondition (and (at ?o home) (free ?b))", 7, "home", 1,
     "expected a parameter such as ?o; constants are not supported"},
    {"argument_of_wrong_type", 7, "    :precondition (and (at ?a ?o) (free ?b))", 7, "?a", 1,
     "expected an argument of type item; ?a is a place"},
    {"duplicate_parameter", 6, "    :parameters (?o - item ?a - place ?a - place)", 6, "?a", 2,
     "parameter ?a is declared twice"},
    {"duplicate_predicate", 4, "  (:predicates (at ?o - item ?p - place) (at ?p - place))", 4, "at ?p", 1,
     "predicate at is declared twice"},
    {"duplicate_type", 3, "  (:types item place item)", 3, "item", 2, "type item is declared twice"},
    {"typing_needs_requirement", 2, "  (:requirements :strips)", 3, "(:types", 1,
     ":types needs :typing in :requirements"},
    {"unsupported_section", 3, "  (:constants home - place)", 3, ":constants", 1,
     "expected :requirements, :types, :predicates or :action, not :constants (not supported)"},
    {"unknown_action_key", 7, "    :pre (and (at ?o ?a) (free ?b))", 7, ":pre", 1,
     "expected :parameters, :precondition or :effect, not :pre"},
    {"conditional_effect", 8, "    :effect (when (free ?b) (at ?o ?b))))", 8, "(when", 1,
     "expected a literal; when effects are not supported"},
    {"not_a_define", 1, "(definition (domain d)", 1, "(", 1, "expected (define (domain NAME) ...)"},
    {"stray_close", 8, "    :effect (and (at ?o ?b) (not (at ?o ?a))))))", 8, ")", 7,
     "expected the end of the file after the closing ')'"},
    {"variable_in_predicate_declaration", 4, "  (:predicates (at o - item ?p - place) (free ?p - place))", 4, "o -",
     1, "expected a variable such as ?o"},
};

INSTANTIATE_TEST_SUITE_P(Table, PddlReaderErrors, ::testing::ValuesIn(kErrorCases),
                         [](const ::testing::TestParamInfo<ErrorCase>& info) { return std::string(info.param.name); });

TEST(PddlReader, MissingParenAtEndOfLastLinePointsPastIt) {
  // Without the trailing newline the error is at the end of line 8.
  std::vector<std::string> lines = base_domain();
  std::string text = join_lines(lines);
  text.pop_back();  // newline
  text.pop_back();  // the final ')'
  auto domain = parse_domain(text, "d.pddl");
  ASSERT_FALSE(domain.has_value());
  EXPECT_EQ(domain.error().message,
            "d.pddl:8:" + std::to_string(lines[7].size()) + ": expected ')' to close the list opened at line 1:1");
}

TEST(PddlReader, DuplicateActionIsRefused) {
  std::vector<std::string> lines = base_domain();
  lines.back().pop_back();  // reopen the define
  lines.push_back("  (:action move :parameters (?o - item) :effect (and)))");
  auto domain = parse_domain(join_lines(lines), "d.pddl");
  ASSERT_FALSE(domain.has_value());
  EXPECT_EQ(domain.error().message, where(lines, 9, "move") + ": action move is declared twice");
}

TEST(PddlReader, TypeCycleIsRefused) {
  std::vector<std::string> lines = base_domain();
  lines[2] = "  (:types item - place place - item)";
  auto domain = parse_domain(join_lines(lines), "d.pddl");
  ASSERT_FALSE(domain.has_value());
  EXPECT_THAT(domain.error().message, HasSubstr("type hierarchy has a cycle"));
  EXPECT_THAT(domain.error().message, ::testing::StartsWith("d.pddl:3:"));
}

// Found by a 10-minute run of fuzz_pddl: "item - - place" was read with
// "-" as the parent type, and the domain written from it did not read back.
TEST(PddlReader, ADashIsNotATypeName) {
  std::vector<std::string> lines = base_domain();
  lines[2] = "  (:types item - - place)";
  auto domain = parse_domain(join_lines(lines), "d.pddl");
  ASSERT_FALSE(domain.has_value());
  EXPECT_THAT(domain.error().message, HasSubstr("expected a type name after '-'"));
  EXPECT_THAT(domain.error().message, ::testing::StartsWith("d.pddl:3:"));
}

// Found by a 10-minute run of fuzz_pddl: a domain without :typing was
// written with "?x0 - object" parameters, which did not read back.
TEST(PddlReader, AnUntypedDomainIsWrittenUntypedAndReadsBack) {
  auto domain = parse_domain("(define (domain d) (:predicates (held ?m)))", "d.pddl");
  ASSERT_TRUE(domain.has_value()) << domain.error().message;
  const std::string written = write_domain(*domain);
  auto again = parse_domain(written, "written.pddl");
  ASSERT_TRUE(again.has_value()) << again.error().message;
  EXPECT_EQ(write_domain(*again), written);
}

TEST(PddlReader, EmptyFile) {
  auto domain = parse_domain("  ; nothing here\n", "empty.pddl");
  ASSERT_FALSE(domain.has_value());
  EXPECT_EQ(domain.error().message, "empty.pddl:2:1: expected '(' but the file is empty");
}

TEST(PddlReader, CommentsAndCaseAreIgnored) {
  std::vector<std::string> lines = base_domain();
  lines[0] = "(DEFINE (Domain D) ; a comment (with a paren";
  lines.insert(lines.begin(), "; header comment )");
  auto domain = parse_domain(join_lines(lines), "d.pddl");
  ASSERT_TRUE(domain.has_value()) << domain.error().describe();
  EXPECT_EQ(domain->name, "d");
}

TEST(PddlReader, DeepNestingIsAnErrorNotACrash) {
  std::string text(100000, '(');
  auto domain = parse_domain(text, "deep.pddl");
  ASSERT_FALSE(domain.has_value());
  EXPECT_THAT(domain.error().message, HasSubstr("nest too deeply"));
}

TEST(PddlReader, MissingFileIsNotFound) {
  auto domain = read_domain_file("/nonexistent/dir/d.pddl");
  ASSERT_FALSE(domain.has_value());
  EXPECT_EQ(domain.error().code, ErrorCode::kNotFound);
  EXPECT_THAT(domain.error().message, HasSubstr("/nonexistent/dir/d.pddl"));
}

// A domain with :equality and :negative-preconditions: grounding drops the
// moves from a place to itself, and the action model checks the rest.
TEST(PddlReader, EqualityDomainGroundsWithoutSelfMoves) {
  std::vector<std::string> lines = base_domain();
  lines[1] = "  (:requirements :strips :typing :equality :negative-preconditions)";
  lines[6] = "    :precondition (and (at ?o ?a) (not (= ?a ?b)) (not (at ?o ?b)))";
  auto domain = parse_domain(join_lines(lines), "d.pddl");
  ASSERT_TRUE(domain.has_value()) << domain.error().describe();
  const ActionSchema& move = domain->actions[0];
  ASSERT_EQ(move.equalities.size(), 1u);
  EXPECT_FALSE(move.equalities[0].positive);
  EXPECT_EQ(move.equalities[0].left, 1);
  EXPECT_EQ(move.equalities[0].right, 2);

  Universe universe;
  TypeId item = *domain->find_type("item");
  TypeId place = *domain->find_type("place");
  ObjectId box = universe.add({"box1", "box", ObjectKind::kItem, item, {}});
  ObjectId a = universe.add({"hall1", "hall", ObjectKind::kSurface, place, {}});
  ObjectId b = universe.add({"room1", "room", ObjectKind::kSurface, place, {}});
  ObjectId c = universe.add({"yard1", "yard", ObjectKind::kSurface, place, {}});
  PredicateId at = *domain->find_predicate("at");
  PredicateId free = *domain->find_predicate("free");
  State state({Fact(at, {box, a}), Fact(free, {a}), Fact(free, {b}), Fact(free, {c})});
  std::vector<ObjectId> all = {box, a, b, c};
  std::vector<Action> actions = ground_actions(*domain, universe, all, state);
  // 3 x 3 place pairs minus the 3 self-moves.
  ASSERT_EQ(actions.size(), 6u);
  for (const Action& action : actions) EXPECT_NE(action.args[1], action.args[2]);

  Action self(0, std::vector<ObjectId>{box, a, a});
  EXPECT_FALSE(is_applicable(*domain, state, self));
  EXPECT_EQ(why_not_applicable(*domain, universe, state, self), "hall1 is the same as hall1");
  Action go(0, std::vector<ObjectId>{box, a, b});
  EXPECT_TRUE(is_applicable(*domain, state, go));
  State moved = apply(*domain, state, go);
  EXPECT_TRUE(moved.holds(Fact(at, {box, b})));
  EXPECT_FALSE(moved.holds(Fact(at, {box, a})));
}

TEST(PddlReader, PositiveEqualityIsEnforcedToo) {
  std::vector<std::string> lines = base_domain();
  lines[1] = "  (:requirements :strips :typing :equality)";
  lines[6] = "    :precondition (and (at ?o ?a) (= ?a ?b))";
  auto domain = parse_domain(join_lines(lines), "d.pddl");
  ASSERT_TRUE(domain.has_value()) << domain.error().describe();
  Universe universe;
  ObjectId box = universe.add({"box1", "box", ObjectKind::kItem, *domain->find_type("item"), {}});
  ObjectId a = universe.add({"hall1", "hall", ObjectKind::kSurface, *domain->find_type("place"), {}});
  ObjectId b = universe.add({"room1", "room", ObjectKind::kSurface, *domain->find_type("place"), {}});
  std::vector<ObjectId> all = {box, a, b};
  std::vector<Action> actions = ground_actions(*domain, universe, all, State());
  ASSERT_EQ(actions.size(), 2u);
  for (const Action& action : actions) EXPECT_EQ(action.args[1], action.args[2]);
  EXPECT_EQ(why_not_applicable(*domain, universe, State(), Action(0, std::vector<ObjectId>{box, a, b})),
            "hall1 differs from room1");
}

TEST(PddlReader, KitchenDomainHasTheExpectedShape) {
  auto domain = read_domain_file(testing::kitchen_domain_path());
  ASSERT_TRUE(domain.has_value()) << domain.error().describe();
  EXPECT_EQ(domain->name, "kitchen");
  std::vector<std::string> actions;
  for (const ActionSchema& a : domain->actions) actions.push_back(a.name);
  EXPECT_EQ(actions, (std::vector<std::string>{"open", "close", "pick-up", "pick-up-from", "put-on", "put-in"}));
  for (const char* p : {"grabbable", "openable", "receptacle", "surface"})
    EXPECT_TRUE(domain->is_static(domain->predicate(p))) << p;
  for (const char* p : {"on", "in", "holding", "handempty", "closed"})
    EXPECT_FALSE(domain->is_static(domain->predicate(p))) << p;
  const TypeId receptacle = *domain->find_type(type_name(ObjectKind::kReceptacle));
  EXPECT_TRUE(domain->is_subtype(receptacle, *domain->find_type("place")));
  EXPECT_FALSE(domain->is_subtype(receptacle, *domain->find_type(type_name(ObjectKind::kSurface))));
  // No type shares its name with a predicate (PDDL tools warn about that).
  for (const TypeInfo& type : domain->types) EXPECT_FALSE(domain->find_predicate(type.name).has_value()) << type.name;
  EXPECT_TRUE(domain->is_subtype(*domain->find_type("item"), kRootType));
}

// Problem files.

class ProblemReader : public ::testing::Test {
 protected:
  void SetUp() override {
    auto domain = parse_domain(join_lines(base_domain()), "d.pddl");
    ASSERT_TRUE(domain.has_value());
    domain_ = std::move(*domain);
  }
  Domain domain_;
};

TEST_F(ProblemReader, ReadsObjectsInitAndGoal) {
  const char* text =
      "(define (problem p) (:domain d)\n"
      "  (:objects box1 box2 - item hall1 room1 - place)\n"
      "  (:init (at box1 hall1) (at box2 hall1) (free room1))\n"
      "  (:goal (and (at box1 room1) (not (at box2 room1)))))\n";
  auto problem = parse_problem(domain_, text, "p.pddl");
  ASSERT_TRUE(problem.has_value()) << problem.error().describe();
  EXPECT_EQ(problem->name, "p");
  EXPECT_EQ(problem->universe.size(), 4u);
  EXPECT_EQ(problem->universe.info(0).category, "box");
  EXPECT_EQ(problem->init.size(), 3u);
  EXPECT_EQ(problem->goal.literals.size(), 2u);
  EXPECT_FALSE(problem->goal.satisfied_by(problem->init));
}

TEST_F(ProblemReader, ErrorsNameFileLineAndColumn) {
  struct Case {
    const char* text;
    const char* message;
  };
  const Case cases[] = {
      {"(define (problem p) (:domain d)\n (:objects box1 - item)\n (:init (at box1 hall1))\n (:goal (at box1 hall1)))",
       "p.pddl:3:18: expected an object; there is no hall1"},
      {"(define (problem p) (:domain d)\n (:objects box1 - crate)\n (:goal (free box1)))",
       "p.pddl:2:19: expected a declared type, not crate"},
      {"(define (problem p) (:domain d)\n (:objects box1 - item))", "p.pddl:1:1: expected a (:goal ...) section"},
      {"(define (problem p) (:domain other)\n (:goal (and)))", "p.pddl:1:21: expected (:domain d)"},
      {"(define (problem p) (:domain d)\n (:objects box1 box1 - item)\n (:goal (free box1)))",
       "p.pddl:2:17: object box1 is declared twice"},
      {"(define (problem p) (:domain d)\n (:objects box1 - item h - place)\n (:goal (free box1)))",
       "p.pddl:3:15: expected an object of type place; box1 is a item"},
      {"(define (problem p) (:domain d)\n (:requirements :strips)\n (:goal (free box1)))",
       "p.pddl:2:3: expected :domain, :objects, :init or :goal, not :requirements"},
      {"(define (domain p))", "p.pddl:1:1: expected (define (problem NAME) ...)"},
  };
  for (const Case& c : cases) {
    auto problem = parse_problem(domain_, c.text, "p.pddl");
    ASSERT_FALSE(problem.has_value()) << c.text;
    EXPECT_EQ(problem.error().code, ErrorCode::kInvalidInput);
    EXPECT_EQ(problem.error().message, c.message) << c.text;
  }
}

}  // namespace
}  // namespace apprentice
