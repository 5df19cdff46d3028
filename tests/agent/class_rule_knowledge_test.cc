// Class rules kept in the store (agent/class_rule_knowledge.h): the rules
// the goals induce are stored with their evidence; one the person forgets
// is no longer proposed, and stays forgotten after a reload, however the
// goals would induce it anew; "forget" finds a rule by what it is about.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "agent/class_rule_knowledge.h"
#include "agent/goal_proposals.h"
#include "agent/concept_source.h"
#include "agent/goal_proposals.h"
#include "common/scenarios.h"
#include "common/scratch.h"
#include "knowledge/store.h"

namespace apprentice {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

class ClassRuleKnowledge : public ::testing::Test {
 protected:
  language::Lexicon lexicon_ = language::Lexicon::open_default();
  LexicalConcepts concepts_{lexicon_, nullptr};
  Scenario scenario_ = testing::shipped_scenario("tidy-kitchen");
  const World& world_ = scenario_.world;
  testing::ScratchDir dir_{true};
  std::string path_ = (dir_ / "knowledge.sqlite").string();

  void SetUp() override {
    if (!lexicon_.has_wordnet()) GTEST_SKIP() << "no WordNet database";
  }
  static Destination in(const std::string& place) {
    return Destination{"in", GoalTemplateArgument{false, place, {}},
                       {GoalTemplateLiteral{"closed", true, {GoalTemplateArgument{false, place, {}}}}}};
  }
  static GoalKnowledge taught(const std::string& kind, const Destination& d) {
    GoalKnowledge g;
    g.key = GoalKey{"tidy kitchen", "clear", kind, "table"};
    g.literals = destination_literals(d);
    g.provenance = Provenance{kind + "1 (" + kind + ")", "instructor"};
    return g;
  }
  // The boxes go in the pantry, the cans in the recycling bin.
  Knowledge taught_knowledge(KnowledgeStore& store) {
    Knowledge knowledge;
    for (const auto& [kind, place] : {std::pair{"cereal-box", "pantry"}, {"pop-tart-box", "pantry"},
                                      {"soda-can", "recycling-bin"}, {"pepsi-can", "recycling-bin"}}) {
      GoalKnowledge g = taught(kind, in(place));
      EXPECT_TRUE(store.save_goal(g));
      knowledge.goals.add(g);
    }
    return knowledge;
  }
  Knowledge reload() {
    auto loaded = load_knowledge_read_only(path_, *world_.domain);
    EXPECT_TRUE(loaded.has_value()) << loaded.error().describe();
    return loaded ? std::move(*loaded) : Knowledge{};
  }
  static std::set<std::string> forgotten_keys(const Knowledge& k) {
    std::set<std::string> keys;
    for (const ClassRule& r : k.forgotten_rules.all()) keys.insert(class_rule_key(r));
    return keys;
  }
  // The classes of the proposer's induced rules that cover a kind never
  // taught (the rules it proposes from).
  std::vector<std::string> rule_classes_proposed(const Knowledge& k, const std::string& kind) {
    GoalProposer proposer(concepts_, k.goals.all(), forgotten_keys(k));
    GoalKey key{"tidy kitchen", "clear", kind, "table"};
    std::vector<std::string> out;
    for (const ClassRule& rule : proposer.induced_for(key))
      if (rule_covers(rule, concepts_.profile(kind)) > 0) out.push_back(rule.class_name);
    return out;
  }
  ObjectId testing_object() const { return *world_.universe->find("ketchup1"); }
};

TEST_F(ClassRuleKnowledge, InducedRulesAreStoredWithTheirEvidence) {
  auto store = KnowledgeStore::open(path_);
  ASSERT_TRUE(store.has_value()) << store.error().describe();
  Knowledge knowledge = taught_knowledge(*store);
  ASSERT_TRUE(keep_induced_rules(knowledge, &*store, concepts_));
  Knowledge loaded = reload();
  ASSERT_FALSE(loaded.class_rules.empty());
  EXPECT_EQ(loaded.class_rules.all(), knowledge.class_rules.all());
  auto box = std::find_if(loaded.class_rules.all().begin(), loaded.class_rules.all().end(),
                          [](const ClassRule& r) { return r.class_name == "box"; });
  ASSERT_NE(box, loaded.class_rules.all().end());
  EXPECT_EQ(box->source, RuleSource::kInduced);
  EXPECT_THAT(box->evidence, ElementsAre("cereal-box", "pop-tart-box"));
  EXPECT_EQ(box->destination, in("pantry"));
  EXPECT_GT(box->confidence, 0.5);
  // A goal forgotten takes its evidence away: at the session's end the
  // stored rules follow the goals.
  ASSERT_TRUE(store->remove_goal(taught("pop-tart-box", in("pantry")).key));
  knowledge.goals.remove(taught("pop-tart-box", in("pantry")).key);
  ASSERT_TRUE(keep_induced_rules(knowledge, &*store, concepts_));
  const Knowledge after = reload();
  for (const ClassRule& r : after.class_rules.all())
    EXPECT_THAT(r.evidence, ::testing::Not(::testing::Contains("pop-tart-box"))) << format_class_rule(r);
}

TEST_F(ClassRuleKnowledge, AForgottenRuleIsNotProposedAndStaysForgottenAfterAReload) {
  auto store = KnowledgeStore::open(path_);
  ASSERT_TRUE(store.has_value()) << store.error().describe();
  Knowledge knowledge = taught_knowledge(*store);
  ASSERT_TRUE(keep_induced_rules(knowledge, &*store, concepts_));
  // Before: the box rule sends a shoe box to the pantry.
  EXPECT_THAT(rule_classes_proposed(knowledge, "shoe-box"), ::testing::Contains("box"));
  std::vector<ClassRule> named = rules_named(class_rules_in_use(knowledge, concepts_), "boxes");
  ASSERT_EQ(named.size(), 1u);
  ASSERT_TRUE(forget_rule(knowledge, &*store, named.front()));
  store = make_error(ErrorCode::kCancelled, "closed");  // closes the store
  Knowledge loaded = reload();
  ASSERT_EQ(loaded.forgotten_rules.size(), 1u);
  EXPECT_EQ(loaded.forgotten_rules.all().front().class_name, "box");
  EXPECT_EQ(loaded.class_rules.find(named.front()), nullptr);
  // The goals still induce it; it is not used.
  for (const ClassRule& r : class_rules_in_use(loaded, concepts_)) EXPECT_NE(r.class_name, "box");
  EXPECT_THAT(rule_classes_proposed(loaded, "shoe-box"), ::testing::Not(::testing::Contains("box")));
  // The can rule is untouched.
  EXPECT_THAT(rule_classes_proposed(loaded, "beer-can"), ::testing::Contains("can"));
  // A later session's end does not store it again.
  auto again = KnowledgeStore::open(path_);
  ASSERT_TRUE(again.has_value());
  ASSERT_TRUE(keep_induced_rules(loaded, &*again, concepts_));
  again = make_error(ErrorCode::kCancelled, "closed");
  const Knowledge after = reload();
  for (const ClassRule& r : after.class_rules.all()) EXPECT_NE(r.class_name, "box");
}

// The proposer, asked about a kind never taught, proposes from the induced
// rules (it once died here, unwinding a throw inside propose()).
TEST_F(ClassRuleKnowledge, TheProposerProposesFromTheRulesForAKindNeverTaught) {
  auto store = KnowledgeStore::open(path_);
  ASSERT_TRUE(store.has_value()) << store.error().describe();
  Knowledge knowledge = taught_knowledge(*store);
  GoalProposer proposer(concepts_, knowledge.goals.all(), forgotten_keys(knowledge));
  GoalKey key{"tidy kitchen", "clear", "shoe-box", "table"};
  bool pantry_by_rule = false;
  for (const DestinationProposal& p : proposer.propose(world_, key, testing_object(), {}))
    if (p.source == ProposalSource::kInducedRule && p.rule && p.rule->class_name == "box") pantry_by_rule = true;
  EXPECT_TRUE(pantry_by_rule);
}

TEST_F(ClassRuleKnowledge, ARuleIsNamedByWhatItIsAboutAndWhereItSendsThings) {
  ClassRule fruit;
  fruit.class_name = "edible fruit";
  fruit.destination = Destination{"on", GoalTemplateArgument{false, "coffee-table", {}}, {}};
  ClassRule other_fruit = fruit;
  other_fruit.rest = true;
  other_fruit.destination = Destination{"in", GoalTemplateArgument{false, "storage-box", {"left"}}, {}};
  ClassRule plastic;
  plastic.modifiers = {"plastic"};
  plastic.destination = fruit.destination;
  std::vector<ClassRule> rules{fruit, other_fruit, plastic};
  auto classes = [&](std::string_view phrase) {
    std::vector<std::string> out;
    for (const ClassRule& r : rules_named(rules, phrase)) out.push_back(rule_subject(r));
    return out;
  };
  EXPECT_THAT(classes("fruits"), ElementsAre("edible fruit", "other edible fruit"));
  EXPECT_THAT(classes("fruit on the coffee table"), ElementsAre("edible fruit"));
  EXPECT_THAT(classes("the rule that other fruit goes in the left storage box"), ElementsAre("other edible fruit"));
  EXPECT_THAT(classes("Edible Fruit goes on the coffee-table"), ElementsAre("edible fruit"));
  EXPECT_THAT(classes("plastic things"), ElementsAre("plastic things"));
  EXPECT_THAT(classes("plastic"), ElementsAre("plastic things"));
  // As a fresh user named a rule read back as "paper stuff".
  EXPECT_THAT(classes("plastic stuff"), ElementsAre("plastic things"));
  EXPECT_THAT(classes("the plastic rule"), ElementsAre("plastic things"));
  EXPECT_THAT(classes("that plastic stuff rule"), ElementsAre("plastic things"));
  EXPECT_THAT(classes("vegetables"), IsEmpty());
  EXPECT_THAT(classes("fruit in the fridge"), IsEmpty());
  EXPECT_THAT(classes(""), IsEmpty());
}

}  // namespace
}  // namespace apprentice
