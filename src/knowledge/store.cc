#include "knowledge/store.h"

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
  auto engine = open_sqlite_store(location, access);
  if (!engine) return tl::unexpected(engine.error());
  return KnowledgeStore(location, std::move(*engine));
}

Result<Knowledge> load_knowledge_read_only(const std::string& location, const Domain& domain) {
  auto store = KnowledgeStore::open(location, StoreAccess::kReadOnly);
  if (!store) return tl::unexpected(store.error());
  return store->load(domain);
}

}  // namespace apprentice
