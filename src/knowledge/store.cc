#include "knowledge/store.h"

#include "knowledge/postgres_store.h"
#include "knowledge/sqlite_store.h"

namespace apprentice {

const TaskKnowledge* Knowledge::find_task(const std::string& name) const {
  for (const TaskKnowledge& t : tasks)
    if (t.name == name) return &t;
  return nullptr;
}

KnowledgeStore::KnowledgeStore(std::filesystem::path location, std::unique_ptr<StoreEngine> engine)
    : location_(std::move(location)), engine_(std::move(engine)) {}
KnowledgeStore::KnowledgeStore(KnowledgeStore&&) noexcept = default;
KnowledgeStore& KnowledgeStore::operator=(KnowledgeStore&&) noexcept = default;
KnowledgeStore::~KnowledgeStore() = default;

Result<KnowledgeStore> KnowledgeStore::open(const std::string& location, StoreAccess access) {
  auto engine = is_postgres_location(location) ? open_postgres_store(location, access) : open_sqlite_store(location, access);
  if (!engine) return tl::unexpected(engine.error());
  return KnowledgeStore(scrub_store_location(location), std::move(*engine));
}

Result<Knowledge> load_knowledge_read_only(const std::string& location, const Domain& domain) {
  auto store = KnowledgeStore::open(location, StoreAccess::kReadOnly);
  if (!store) return tl::unexpected(store.error());
  return store->load(domain);
}

Result<KnowledgeCopy> copy_knowledge(const std::string& from, const std::string& to, const Domain& domain) {
  auto knowledge = load_knowledge_read_only(from, domain);
  if (!knowledge) return tl::unexpected(knowledge.error());
  auto store = KnowledgeStore::open(to, StoreAccess::kReadWrite);
  if (!store) return tl::unexpected(store.error());
  KnowledgeCopy copied;
  for (const TaskKnowledge& task : knowledge->tasks) {
    if (auto s = store->save_task(task); !s) return tl::unexpected(s.error());
    ++copied.tasks;
  }
  for (const GoalKnowledge& goal : knowledge->goals.all()) {
    if (auto s = store->save_goal(goal); !s) return tl::unexpected(s.error());
    ++copied.goals;
  }
  for (const Rule& rule : knowledge->rules.rules()) {
    if (auto s = store->save_rule(domain, rule); !s) return tl::unexpected(s.error());
    ++copied.rules;
  }
  for (const ClassRule& rule : knowledge->class_rules.all()) {
    if (auto s = store->save_class_rule(rule); !s) return tl::unexpected(s.error());
    ++copied.class_rules;
  }
  // What was forgotten there stays forgotten here.
  for (const ClassRule& rule : knowledge->forgotten_rules.all()) {
    if (auto s = store->forget_class_rule(rule); !s) return tl::unexpected(s.error());
    ++copied.forgotten_rules;
  }
  return copied;
}

}  // namespace apprentice
