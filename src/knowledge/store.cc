#include "knowledge/store.h"

#include "knowledge/postgres_store.h"
#include "knowledge/sqlite_store.h"

namespace apprentice {

const TaskKnowledge* Knowledge::find_task(const std::string& name) const {
  for (const TaskKnowledge& t : tasks)
    if (t.name == name) return &t;
  return nullptr;
}

KnowledgeStore::KnowledgeStore(std::filesystem::path location, std::string household, std::string robot,
                               std::unique_ptr<StoreEngine> engine)
    : location_(std::move(location)), household_(std::move(household)), robot_(std::move(robot)),
      engine_(std::move(engine)) {}
KnowledgeStore::KnowledgeStore(KnowledgeStore&&) noexcept = default;
KnowledgeStore& KnowledgeStore::operator=(KnowledgeStore&&) noexcept = default;
KnowledgeStore::~KnowledgeStore() = default;

Result<KnowledgeStore> KnowledgeStore::open(const std::string& location, StoreAccess access, const std::string& household,
                                            const std::string& robot) {
  if (auto s = check_household_name(household); !s) return tl::unexpected(s.error());
  const std::string name = robot.empty() ? default_robot_name() : robot;
  if (auto s = check_robot_name(name); !s) return tl::unexpected(s.error());
  auto engine = is_postgres_location(location) ? open_postgres_store(location, access, household, name)
                                               : open_sqlite_store(location, access, household, name);
  if (!engine) return tl::unexpected(engine.error());
  return KnowledgeStore(scrub_store_location(location), household, name, std::move(*engine));
}

Result<Knowledge> load_knowledge_read_only(const std::string& location, const Domain& domain, const std::string& household) {
  auto store = KnowledgeStore::open(location, StoreAccess::kReadOnly, household);
  if (!store) return tl::unexpected(store.error());
  return store->load(domain);
}

namespace {

// Copies one household's tasks, goals and class rules (and, with `rules`, the shared
// rules) from `from` into `to`.
Status copy_household(const KnowledgeStore& from, KnowledgeStore& to, const Domain& domain, bool rules,
                      KnowledgeCopy& copied) {
  auto knowledge = from.load(domain);
  if (!knowledge) return tl::unexpected(knowledge.error());
  for (const TaskKnowledge& task : knowledge->tasks) {
    if (auto s = to.save_task(task); !s) return s;
    ++copied.tasks;
  }
  for (const GoalKnowledge& goal : knowledge->goals.all()) {
    if (auto s = to.save_goal(goal); !s) return s;
    ++copied.goals;
  }
  for (const ClassRule& rule : knowledge->class_rules.all()) {
    if (auto s = to.save_class_rule(rule); !s) return s;
    ++copied.class_rules;
  }
  // What was forgotten there stays forgotten here.
  for (const ClassRule& rule : knowledge->forgotten_rules.all()) {
    if (auto s = to.forget_class_rule(rule); !s) return s;
    ++copied.forgotten_rules;
  }
  if (!rules) return {};
  for (const Rule& rule : knowledge->rules.rules()) {
    if (auto s = to.save_rule(domain, rule); !s) return s;
    ++copied.rules;
  }
  return {};
}

}  // namespace

Result<KnowledgeCopy> copy_knowledge(const std::string& from, const std::string& to, const Domain& domain) {
  auto source = KnowledgeStore::open(from, StoreAccess::kReadOnly);
  if (!source) return tl::unexpected(source.error());
  auto households = source->households();
  if (!households) return tl::unexpected(households.error());
  KnowledgeCopy copied;
  // The default household first, with the shared rules, even when it has
  // nothing of its own.
  auto target = KnowledgeStore::open(to, StoreAccess::kReadWrite);
  if (!target) return tl::unexpected(target.error());
  if (auto s = copy_household(*source, *target, domain, true, copied); !s) return tl::unexpected(s.error());
  for (const std::string& household : *households) {
    if (household == kDefaultHousehold) continue;
    auto from_household = KnowledgeStore::open(from, StoreAccess::kReadOnly, household);
    if (!from_household) return tl::unexpected(from_household.error());
    auto to_household = KnowledgeStore::open(to, StoreAccess::kReadWrite, household);
    if (!to_household) return tl::unexpected(to_household.error());
    if (auto s = copy_household(*from_household, *to_household, domain, false, copied); !s)
      return tl::unexpected(s.error());
  }
  copied.households = households->size();
  return copied;
}

}  // namespace apprentice
