// Inside read_reply (language/reply.h): the readers of each kind of
// question, and the resolution of a reply's noun phrases in the world.
// Not for use outside the language module.
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "language/grounding.h"
#include "language/reference.h"
#include "language/reply.h"
#include "language/reply_clauses.h"

namespace apprentice::language {

// A command said as the whole reply ("help", "undo", "forget the glasses"),
// or nullopt.
std::optional<Command> command(const Grounder& grounder, const World& world, std::string_view text);

// A reply, read once into words, with what it is read against.
struct ReplyInput {
  const Grounder& grounder;
  const World& world;
  const ReplyContext& context;
  std::vector<std::string> words;  // reply_words, then join_world_names
  ReplyVocabulary vocabulary;

  ReplyInput(const Grounder& g, const World& w, const ReplyContext& c, std::vector<std::string> ws);
};

// Why a reply cannot be used: the reason in plain English, and the
// grounder's failure where there is one.
struct Problem {
  std::string reason;
  std::optional<GroundingFailure> failure;
};

Unusable unusable(const ReplyInput& in, const Problem& problem);

// What a noun phrase of the reply names.
using Choice = std::variant<ObjectId, Ambiguous, Problem>;

class Resolver {
 public:
  explicit Resolver(const ReplyInput& in);

  // Every object the phrase may name. A pronoun is the object asked about
  // (a place pronoun, or any pronoun when `role` is a place, the place named
  // last); door words name the door's receptacle; "the mug on the counter"
  // keeps only what is there.
  std::variant<std::vector<ObjectId>, Problem> candidates(const Chunk& chunk, Role role) const;
  // The one thing a phrase names: the object asked about if it fits, else
  // the only candidate, else the first of look-alikes no one can tell apart
  // (same kind, place and properties), else the question which.
  // `recent`: whether the conversation's place named last settles
  // look-alikes ("close the drawer" after a placement in the top drawer);
  // a new destination ("in the drawer") is asked which, unless this reply
  // named one of them.
  Choice choose(const Chunk& chunk, Role role, bool recent = true) const;
  Choice choose(const std::vector<ObjectId>& objects, const std::string& phrase, Role role, bool recent = true) const;

  // Whether the phrase, which names something else first, may also name
  // the object asked about: its name ends with the phrase's noun as a
  // closed compound ("the paper" for the newspaper) or WordNet relates them.
  bool fits_asked(const Chunk& chunk) const;

  // The place named last: in this reply, else the conversation's.
  std::optional<ObjectId> last_place() const { return last_place_ ? last_place_ : in_.context.recent_place; }
  void named_place(ObjectId place) { last_place_ = place; }
  ReferenceContext reference_context() const;

 private:
  std::variant<std::vector<ObjectId>, Problem> located(std::vector<ObjectId> objects, const Chunk& chunk) const;

  const ReplyInput& in_;
  std::optional<ObjectId> last_place_;
};

Reply read_task(const ReplyInput& in);
Reply read_structure(const ReplyInput& in);  // kTaskStep and kSubtaskEnd
Reply read_goal(const ReplyInput& in);
Reply read_action(const ReplyInput& in);
Reply read_yes_no(const ReplyInput& in);
Reply read_which(const ReplyInput& in);

// The longest yes or no phrase the words start with: its length, and the
// answer ("yes, please" -> {2, true}); nullopt if they start with none.
std::optional<std::pair<std::size_t, bool>> answer_prefix(const std::vector<std::string>& words);

// The words cut at "," only: "the kitchen is a mess, please tidy it" is two.
std::vector<std::vector<std::string>> comma_pieces(const std::vector<std::string>& words);
// A word of the world's location ("living" of "living room"): never the
// task's verb.
bool names_location(const std::string& word, const ReplyInput& in);

// Why a reply at a question about the task's steps names no part:
// "First tell me the parts of the task, such as "clear the table"; I will
// ask where each thing goes when I come to it." (`example`: the first
// reply that would work there).
std::string parts_come_first(std::string_view example);

// The finished expressions of task-structure questions.
bool says_finished(const std::vector<std::string>& words, const ReplyInput& in);
// Whether the reply says only that something ends ("I'm done", "that's it
// for the counter, leave the rest"): each of its clauses ends something,
// leaves things, or is fillers. "put it in the fridge and then you're done
// with the table" says more.
bool says_only_an_ending(const std::vector<std::string>& words, const ReplyInput& in);

// read_reply without the readings by reference to others below: the
// commands, the script's grammar, then the question's own reader.
Reply read_reply_plain(const Grounder& grounder, const World& world, const ReplyContext& context,
                       std::string_view text);

// At a goal question, what the question's own reading (`first`) could not
// use, read by reference to other things (reply_others.cc): "skip it",
// "socks too", "same as the hammer", a goal for another thing still to
// come, "clothes go in the hamper", "the rest on the floor".
std::optional<Reply> read_goal_by_others(const Grounder& grounder, const World& world, const ReplyContext& context,
                                         std::string_view text, const Reply& first);

// "everything else goes in the hamper", read whole by the goal's reader as
// one thing's goal: the same goal for the rest of the things still to come.
std::optional<Reply> read_goal_with_rest(const Grounder& grounder, const World& world, const ReplyContext& context,
                                         std::string_view text, const Reply& first);

// "clear", "put away": a verb and its particle as a subtask's name.
std::string verb_name(const std::string& verb, const std::string& particle);

}  // namespace apprentice::language
