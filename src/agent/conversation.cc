// The line to the teacher (agent/conversation.h).
#include "agent/conversation.h"

#include "util/check.h"

namespace apprentice {

Result<Conversation::Said> Conversation::next_reply(const Question& asked, const World& world, bool about_steps) {
  APPRENTICE_CHECK(dialogue_ != nullptr);
  if (!answers_ahead_.empty()) {
    Said said{std::move(answers_ahead_.front()), false};
    answers_ahead_.pop_front();
    return said;
  }
  if (about_steps && !steps_ahead_.empty()) {
    Said said{std::move(steps_ahead_.front()), true};
    steps_ahead_.pop_front();
    return said;
  }
  auto text = dialogue_->ask_uncounted(asked, world);
  if (!text) return tl::unexpected(text.error());
  return Said{std::move(*text), false};
}

}  // namespace apprentice
