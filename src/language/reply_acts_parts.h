// Inside read_acts (reply_acts.cc): the kinds of segment a reply is cut
// into (reply_segments.cc), the answer's words read with slips and words
// that carry nothing (reply_answer_words.cc), and several steps in one
// reply (reply_steps.cc). Not for use outside the language module.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "language/grounding.h"
#include "language/reply.h"

namespace apprentice::language::acts {

using Words = std::vector<std::string>;

// --- Segments (reply_segments.cc) ----------------------------------------

// Words that only set the tone: "um", "ugh", "lol", "ok so", "oh and".
bool is_interjection(std::string_view w);
// The words of a correction's marker: "no wait", "oops", "nah", "wait what".
bool is_marker(std::string_view w);

struct Segment {
  std::string text;  // as typed
  Words words;       // reply_words
};

// The reply cut at , ; : . ! ? and free-standing dashes.
std::vector<Segment> segments(std::string_view text);
Words without_interjections(Words words);
// "and", "then", "now" before a part or an action ("and then the table",
// "now shut the cupboard"): they join it to what came before.
bool is_connective(std::string_view w);
Words without_leading_connectives(Words words);
bool has(const Words& words, std::initializer_list<std::string_view> phrase);
// "undo", "scratch that", "go back one", "that was wrong": how many undos
// (0: not an undo).
int undos(const Words& said);
// "shelf was right", "the bottom was right before": the place a thing was
// at, said right, which confirms an undo said with it.
bool confirms_the_old_place(const Words& said);

// Leading marker words of a correction, and whether they are strong ("no
// wait", "oops", "I meant") or could be a filler ("nah", "no").
struct Marker {
  std::size_t length = 0;
  bool strong = false;
};
Marker marker(const Words& words);

// "pan in the sink, knife too", "sandpaper in the bottom drawer and the
// batteries as well", "top drawer. ruler and calculator too": the answer
// before the clauses that say "the same for" other things, and those
// clauses ("knife too"); none when the answer ends with no such clause.
std::pair<std::string, std::vector<std::string>> without_trailing_toos(std::string_view answer);
// The goals of the things a "knife too" names, like the goal `given` the
// thing asked about (`at.object`); added to its others.
void add_the_same_for(const Grounder& grounder, const World& world, const ReplyContext& at,
                      const std::vector<std::string>& toos, GoalGiven& given);

// "what's left?", "where's the soap?", "why did you close it?": the
// teacher's question, or nullopt.
std::optional<Command> question(const Grounder& grounder, const World& world, const Words& said);
// "stop for now", "gotta go": the teacher ends the session.
bool ends_session(const Words& said, Asked asked);
// "what can you do?", "what do I type here?": the teacher asks what to say.
bool asks_for_help(const Words& said);
// "you left it open", "someone left the lid up": where the words tell
// what a person did (not what the agent should do); words.size() when
// they tell none.
std::size_t what_someone_did_from(const Words& words);
// "close the top drawer", "shut both drawers": the actions, or nullopt when
// the segment is not such a command.
std::optional<std::vector<Action>> door_action(const Grounder& grounder, const World& world,
                                               const ReplyContext& context, const Words& said);
// A door the teacher wants left open from now on: "leave the washer open
// from now on", "always keep the cabinet open", "i want it left open",
// "the hamper should stay open", "don't close the washer anymore". The
// openings of those doors (door_action's reading of "open X"; each action's
// first argument is a door); nullopt when the words say no such thing.
std::optional<std::vector<Action>> doors_left_open(const Grounder& grounder, const World& world,
                                                   const ReplyContext& context, const Words& said);
// A door the teacher wants closed from now on: "this one stays closed",
// "the bottom drawer should always be shut", "keep the cabinet closed from
// now on", "always close the toy box". The closings of those doors
// (door_action's reading of "close X"); nullopt when the words say no such
// thing (a closing said for now, "close the drawer", is door_action's).
std::optional<std::vector<Action>> doors_kept_closed(const Grounder& grounder, const World& world,
                                                     const ReplyContext& context, const Words& said);

// --- The answer's words (reply_answer_words.cc) ---------------------------

bool usable(const Reply& r);
// The place a goal puts the thing asked about.
std::optional<ObjectId> destination(const World& world, const Reply& reply);
// A word of the world's names a typed word is a slip of ("hampr" for
// "hamper"); "" when none or several.
std::string slip_of(const World& world, const std::string& word);
std::string quote(const std::string& s);
// The first word of a phrase nothing here fits that only describes ("wet",
// "obviously"); "" when none.
std::string unmodelled_modifier(const Grounder& grounder, const World& world, const Words& phrase);
// The answer's words read at the question, words that carry nothing
// skipped when the rest then reads whole (`notes` say so).
Reply read_answer(const Grounder& grounder, const World& world, const ReplyContext& context, std::string text,
                  std::vector<std::string>& notes);
// Segments that name nothing here and hold no instruction: remarks.
bool is_remark(const Grounder& grounder, const World& world, const Words& words);
// "I'll wear it", "more stuff is going in", "there's another one", "so I
// can grab it in the dark": a clause with a subject of its own (or a
// reason's conjunction) that names nothing here and says no place: why,
// told after the answer, not what to do.
bool says_why(const Grounder& grounder, const World& world, const Words& words);
// "leave it open so I can grab it in the dark": the words before a reason
// said inside a segment; nullopt when it holds none.
std::optional<Words> without_reason(const Grounder& grounder, const World& world, const Words& words);
std::string joined(const std::vector<const Segment*>& parts);

// --- Several steps (reply_steps.cc) --------------------------------------

// "clear the counter, then the table": the first step's reading and the
// further steps as said; nullopt when the reply is one step, or a part does
// not read. `whole`: the reply read whole at the question (read_reply).
// Where things go, said after a part ("the folding table next. detergent
// and stain remover go in the cabinet"), is no step: it goes to
// `goals_ahead`, as said.
std::optional<std::pair<Reply, std::vector<std::string>>> several_steps(const Grounder& grounder, const World& world,
                                                                      const ReplyContext& context,
                                                                      std::string_view text, const Reply& whole,
                                                                      std::vector<std::string>& goals_ahead);

// --- read_acts (reply_acts.cc) -------------------------------------------

ReplyActs read(const Grounder& grounder, const World& world, const ReplyContext& context, std::string_view text);

}  // namespace apprentice::language::acts
