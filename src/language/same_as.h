// Replies that give the thing asked about another thing's goal, instead of
// saying where it goes: "same as the soda can" names the other thing;
// "socks too" and "same again" mean the goal just given.
//
// These are readings of the words alone. Whether the other thing is known,
// and what goal it had, is the agent's to find (agent/agent_goals.cc).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace apprentice::language {

// "same as the soda can", "the same place as the mug", "like the soda
// cans", "where the soda can goes", "crayons go with the blocks": the
// other thing's name ("soda can", "soda cans"; "" when the reply names
// none), and what the reply says after it ("same as the hammer, and shut
// the drawer" -> "shut the drawer"). A location after the name is dropped:
// "the book on the floor" -> "book".
struct SameAs {
  std::string other;
  std::string more;
  // What is said to go like the other, where a reply names it: "the
  // highlighter" in "the highlighter goes with the pens"; "" otherwise.
  std::string subject = {};
};
SameAs read_same_as(std::string_view reply);

// "socks too", "the sock as well", "same again", "the same", "same for
// this one", "ditto", "that too", "same as before": the reply gives the
// thing asked about the goal given last. Returns the phrase that names the
// thing asked about ("socks", "sock"), "" when none is named ("same again",
// "that too", "it too"), or nothing when the reply is not of this form.
std::optional<std::string> read_same_again(std::string_view reply);

}  // namespace apprentice::language
