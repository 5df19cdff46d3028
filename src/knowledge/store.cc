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

bool is_postgres_location(std::string_view location) {
  return location.starts_with("postgresql://") || location.starts_with("postgres://");
}

std::string scrub_store_location(std::string_view location) {
  if (!is_postgres_location(location)) return std::string(location);
  const std::size_t start = location.find("://") + 3;
  std::size_t end = location.find_first_of("/?#", start);
  if (end == std::string_view::npos) end = location.size();
  std::string authority(location.substr(start, end - start));
  // user:password@host: the userinfo is everything before the last '@'.
  if (auto at = authority.rfind('@'); at != std::string::npos) {
    std::string user = authority.substr(0, at);
    if (auto colon = user.find(':'); colon != std::string::npos) user.resize(colon);
    authority = user + authority.substr(at);
  }
  std::string rest(location.substr(end));
  std::string out = std::string(location.substr(0, start)) + authority;
  // Query parameters: every one but password=.
  const std::size_t query = rest.find('?');
  out += rest.substr(0, query);
  if (query == std::string::npos) return out;
  std::string kept;
  std::string_view parameters = std::string_view(rest).substr(query + 1);
  while (!parameters.empty()) {
    const std::size_t amp = parameters.find('&');
    std::string_view parameter = parameters.substr(0, amp);
    if (!parameter.starts_with("password=") && parameter != "password" && !parameter.empty())
      kept += (kept.empty() ? "?" : "&") + std::string(parameter);
    if (amp == std::string_view::npos) break;
    parameters.remove_prefix(amp + 1);
  }
  return out + kept;
}

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
  return copied;
}

}  // namespace apprentice
