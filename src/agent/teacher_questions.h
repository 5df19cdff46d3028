// The teacher's own questions answered from what the agent knows and how
// far the teaching has come: "why did you do that?", "why did you put the
// glove in the right basket?", "why is the closet still open?", "what's
// left?", "status". A part of the teaching session (agent/session.h) with
// no state of its own: it reads, says what to say, and changes nothing,
// so it is tested without a session or a teacher.
#pragma once

#include <span>
#include <string>

#include "agent/curriculum.h"
#include "knowledge/goal_memory.h"
#include "world/world.h"

namespace apprentice {

// A yes/no the agent asked about a thing: the goal it proposed, and the
// evidence the question showed ("with clean diapers, as you said").
struct ProposalAsked {
  ObjectId thing = 0;
  Goal goal;
  std::string evidence;
};

// What the answers read: the world as it is now, the goals known, how far
// the teaching has come, the teacher's last lesson (null before any), and
// the yes/no questions asked, in order.
struct TeachingSoFar {
  const World& world;
  const GoalMemory& goals;
  const teaching::Curriculum& progress;
  const std::string* last_reply = nullptr;
  std::span<const ProposalAsked> asked = {};
};

// What a "why?" asks about: things as they are; what was done before
// ("why'd you throw out the bottle before?"); or a question the agent
// asked ("why did you ask if the blanket goes with clean diapers?").
enum class WhyAbout { kNow, kEarlier, kAsking };

// The goal known for things of `kind`: that of the part under way, else of
// this task, else any; null when none is.
const GoalKnowledge* goal_known_for(const TeachingSoFar& so_far, const std::string& kind);

// The answer to "why ...?" naming `named` (the things, then the places the
// question names, language::Command::things): about the first named thing
// with a goal known, or the first door named; with none, about the last
// goal the agent decided alone, else the teacher's last lesson. A thing
// named with a place it no longer goes to, or asked about `earlier`
// ("before"), is answered with how it came to go there when it was dealt
// with, and where it goes now.
// Asked `kAsking`, it is answered with the evidence of the last yes/no
// about a thing named (a thing of its kind, else the last yes/no asked).
std::string answer_why(const TeachingSoFar& so_far, std::span<const ObjectId> named, WhyAbout about = WhyAbout::kNow);

// "what's left?": within a part of the task, the things still on its
// places (not the one being worked on); between parts, the parts done and
// every thing not dealt with yet, where it is (the agent cannot know which
// of them the task means); before the task, that there is none yet.
std::string answer_whats_left(const TeachingSoFar& so_far);

// "status": what the agent sees, then what it is doing, asking about
// `asking_about` (the question pending), with the counts learned and of
// the teacher's instructions.
struct StatusCounts {
  long long rules = 0;
  long long instructions = 0;
};
std::vector<std::string> answer_status(const TeachingSoFar& so_far, std::optional<ObjectId> asking_about,
                                       StatusCounts counts);

// The kinds of thing with a learned goal that `phrase` names, here or not:
// exactly, by a plural, or by the last word ("plates": ceramic-plate,
// paper-plate). What "forget plates" forgets.
std::vector<std::string> kinds_known_by(const GoalMemory& goals, std::string_view phrase);

}  // namespace apprentice
