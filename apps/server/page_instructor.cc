#include "page_instructor.h"

#include "language/narration.h"
#include "world_view.h"

namespace apprentice::serve {

namespace {

// The replies a question's buttons send: the two answers of a yes/no
// question, the two of "Is there more to clear on the table, or is that
// all?" (a subtask's step asked about no thing, instructor.h), the things a
// "Which ...?" question offers. Each is a reply a person could type, read
// as any typed reply is.
nlohmann::json choices(const Question& question, const World& world) {
  nlohmann::json out = nlohmann::json::array();
  if (is_yes_no(question.kind)) {
    out.push_back({{"label", "Yes"}, {"reply", "yes"}});
    out.push_back({{"label", "No"}, {"reply", "no"}});
  }
  if (question.kind == QuestionKind::kSubtaskStep && !question.object) {
    out.push_back({{"label", "There is more"}, {"reply", "there is more"}});
    out.push_back({{"label", "That's all"}, {"reply", "that's all"}});
  }
  for (ObjectId choice : question.choices) {
    std::string name = language::spoken_name(world, choice);
    out.push_back({{"label", language::capitalize(bare_name(world, choice))}, {"reply", name}, {"id", world.universe->name(choice)}});
  }
  return out;
}

}  // namespace

void PageInstructor::report_knowledge_changes(const nlohmann::json& knowledge) {
  std::set<std::string> now;
  for (const nlohmann::json& entry : knowledge) now.insert(entry.value("text", ""));
  nlohmann::json learned = nlohmann::json::array(), forgotten = nlohmann::json::array();
  for (const std::string& text : now)
    if (!known_.contains(text)) learned.push_back(text);
  for (const std::string& text : known_)
    if (!now.contains(text)) forgotten.push_back(text);
  if (!learned.empty()) events_.append({{"type", "learned"}, {"items", learned}});
  if (!forgotten.empty()) events_.append({{"type", "forgotten"}, {"items", forgotten}});
  known_ = std::move(now);
}

Result<std::string> PageInstructor::answer(const Question& question, const World& world) {
  nlohmann::json knowledge = views_.knowledge ? views_.knowledge() : nlohmann::json::array();
  report_knowledge_changes(knowledge);
  nlohmann::json body{{"type", "question"},
                      {"text", question.text},
                      {"kind", to_string(question.kind)},
                      {"object", question.object ? nlohmann::json(world.universe->name(*question.object)) : nlohmann::json()},
                      {"choices", choices(question, world)},
                      {"world", world_view(world)},
                      {"knowledge", std::move(knowledge)},
                      {"progress", views_.progress ? views_.progress(world) : nlohmann::json()}};
  std::string reply;
  {
    std::unique_lock lock(mutex_);
    if (cancelled_) return make_error(ErrorCode::kCancelled, "the session was ended");
    // Appended under the lock, so that a reply to this question (posted as
    // soon as the page sees it) finds it waiting.
    waiting_ = events_.append(std::move(body));
    reply_.reset();
    replied_.wait(lock, [&] { return reply_.has_value() || cancelled_; });
    waiting_.reset();
    if (!reply_) return make_error(ErrorCode::kCancelled, "the session was ended");
    reply = std::move(*reply_);
    reply_.reset();
  }
  events_.append({{"type", "reply"}, {"text", reply}});
  return reply;
}

void PageInstructor::hear(std::string_view statement) {
  events_.append({{"type", "say"}, {"text", std::string(statement)}});
}

void PageInstructor::observe(const Action& action, const World& world) {
  nlohmann::json objects = nlohmann::json::array();
  for (ObjectId arg : action.arguments()) objects.push_back(world.universe->name(arg));
  events_.append({{"type", "action"},
                  {"text", language::capitalize(language::action_phrase(world, action)) + "."},
                  {"objects", objects},
                  {"world", world_view(world)}});
}

Status PageInstructor::post(std::string reply, std::uint64_t question) {
  {
    std::lock_guard lock(mutex_);
    if (cancelled_) return make_error(ErrorCode::kCancelled, "this session has ended");
    if (waiting_ != question || reply_)
      return make_error(ErrorCode::kFailedPrecondition,
                        "that question is no longer waiting for an answer (it was answered, perhaps in another tab)");
    reply_ = std::move(reply);
  }
  replied_.notify_all();
  return {};
}

void PageInstructor::cancel() {
  {
    std::lock_guard lock(mutex_);
    cancelled_ = true;
  }
  replied_.notify_all();
}

}  // namespace apprentice::serve
