// The PDDL writer: what it writes reads back as the same domain and the
// same problem, so any PDDL planner sees what apprentice sees.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <set>

#include "world/pddl.h"
#include "world_fixtures.h"

namespace apprentice {
namespace {

using testing::load_or_die;
using testing::tidy_kitchen_path;

// A domain's content, by names rather than ids, for comparing two readings.
std::string describe(const Domain& d) {
  std::string out = d.name + "|";
  for (const std::string& r : d.requirements) out += r + ",";
  out += "|";
  for (const TypeInfo& t : d.types) out += t.name + "<" + d.types[t.parent].name + ",";
  out += "|";
  for (const PredicateSchema& p : d.predicates) {
    out += p.name + "(";
    for (TypeId t : p.parameter_types) out += d.types[t].name + " ";
    out += ")";
  }
  for (const ActionSchema& a : d.actions) {
    out += "|" + a.name + "(";
    for (const Parameter& p : a.parameters) out += p.name + ":" + d.types[p.type].name + " ";
    out += ") pre";
    for (const LiteralSchema& l : a.preconditions) {
      out += std::string(l.positive ? " +" : " -") + d.predicates[l.atom.predicate].name;
      for (auto i : l.atom.parameters) out += "." + std::to_string(i);
    }
    for (const EqualitySchema& e : a.equalities)
      out += std::string(e.positive ? " =" : " !=") + std::to_string(e.left) + std::to_string(e.right);
    out += " add";
    for (const AtomSchema& x : a.add_effects) {
      out += " " + d.predicates[x.predicate].name;
      for (auto i : x.parameters) out += "." + std::to_string(i);
    }
    out += " del";
    for (const AtomSchema& x : a.delete_effects) {
      out += " " + d.predicates[x.predicate].name;
      for (auto i : x.parameters) out += "." + std::to_string(i);
    }
  }
  return out;
}

std::set<std::string> facts_of(const Domain& domain, const Universe& universe, const State& state) {
  std::set<std::string> out;
  for (const Fact& f : state.facts()) out.insert(format_fact(domain, universe, f));
  return out;
}

TEST(PddlWriter, KitchenDomainRoundTrips) {
  auto domain = read_domain_file(testing::kitchen_domain_path());
  ASSERT_TRUE(domain.has_value()) << domain.error().describe();
  std::string written = write_domain(*domain);
  auto again = parse_domain(written, "written.pddl");
  ASSERT_TRUE(again.has_value()) << again.error().describe() << "\n" << written;
  EXPECT_EQ(describe(*again), describe(*domain));
  EXPECT_EQ(again->static_predicates, domain->static_predicates);
  // Writing is a fixed point.
  EXPECT_EQ(write_domain(*again), written);
}

TEST(PddlWriter, EqualityAndNegationSurviveTheRoundTrip) {
  const char* text =
      "(define (domain d) (:requirements :strips :typing :equality :negative-preconditions)\n"
      " (:types a b - object c - a)\n"
      " (:predicates (p ?x - a) (q ?x - a ?y - b) (r))\n"
      " (:action go :parameters (?x - a ?z - c ?y - b)\n"
      "   :precondition (and (p ?x) (not (q ?x ?y)) (not (= ?x ?z)) (r))\n"
      "   :effect (and (q ?x ?y) (not (r)) (not (p ?x)))))\n";
  auto domain = parse_domain(text, "d.pddl");
  ASSERT_TRUE(domain.has_value()) << domain.error().describe();
  auto again = parse_domain(write_domain(*domain), "written.pddl");
  ASSERT_TRUE(again.has_value()) << again.error().describe() << "\n" << write_domain(*domain);
  EXPECT_EQ(describe(*again), describe(*domain));
}

TEST(PddlWriter, ScenarioProblemRoundTrips) {
  Scenario scenario = load_or_die(tidy_kitchen_path());
  const World& world = scenario.world;
  auto goal = parse_goal(*world.domain, *world.universe, "(and (in ketchup1 fridge1) (closed fridge1))");
  ASSERT_TRUE(goal.has_value());
  std::string written = write_problem(scenario.name, *world.domain, *world.universe, world.state, *goal);
  auto problem = parse_problem(*world.domain, written, "problem.pddl");
  ASSERT_TRUE(problem.has_value()) << problem.error().describe() << "\n" << written;
  EXPECT_EQ(problem->name, "tidy-kitchen");
  ASSERT_EQ(problem->universe.size(), world.universe->size());
  for (const ObjectInfo& o : world.universe->objects()) {
    auto id = problem->universe.find(o.id);
    ASSERT_TRUE(id.has_value()) << o.id;
    const ObjectInfo& read = problem->universe.info(*id);
    EXPECT_EQ(read.type, o.type) << o.id;
    EXPECT_EQ(read.category, o.category) << o.id;
    // Places stay places: search relies on the kind to know what matters.
    EXPECT_EQ(read.kind, o.kind) << o.id;
  }
  EXPECT_EQ(facts_of(*world.domain, problem->universe, problem->init),
            facts_of(*world.domain, *world.universe, world.state));
  EXPECT_EQ(format_goal(*world.domain, problem->universe, problem->goal),
            format_goal(*world.domain, *world.universe, *goal));
  // Writing the re-read problem gives the same text.
  EXPECT_EQ(write_problem(problem->name, *world.domain, problem->universe, problem->init, problem->goal), written);
}

}  // namespace
}  // namespace apprentice
