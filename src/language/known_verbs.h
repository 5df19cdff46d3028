// The verbs the agent names a task and its steps by, and how a verb the
// teacher uses instead is taken as one of them (issue 21: "clean up the
// craft room" is the tidy task; "unpack the bags" is emptying them).
//
// The agent's own vocabulary is small: a task is tidying a room; a step
// clears what is on a surface or empties what is in a receptacle; the
// paper's script also stores what is on a counter and unloads a rack. Each
// is kept with the WordNet senses the agent means by it, so that a
// teacher's verb is compared with those senses only ("clear" in "clear
// up a mystery" is not clearing a table). A verb is taken as a known one
// when, in one of its commonest senses, WordNet puts it in the same synset,
// directly above or below, in the same verb group, or beside it under one
// hypernym; the closest wins, and between equally close step verbs the
// one for the place's kind. Without WordNet, or with nothing close enough,
// the teacher's verb is kept as said.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "language/lexicon.h"
#include "world/universe.h"

namespace apprentice::language {

// A verb taken as a known one, and the note the read-back says.
struct VerbTaken {
  std::string verb;  // the known verb: "tidy"
  std::string note;  // "I took \"clean up\" as tidying."
};

// The task verb a verb said for a task over a room stands for; nullopt
// when it is a known task verb itself, or no known one is close.
// `said`: the verb and its particle as said ("clean up", "clean").
std::optional<VerbTaken> known_task_verb(const Lexicon& lexicon, std::string_view verb, std::string_view particle);

// A verb said over everything in the room ("put everything away", "get it
// all sorted"): the task over the room the agent knows, tidying, with the
// note the read-back says; nullopt when the verb is a known task verb.
std::optional<VerbTaken> task_verb_over_everything(std::string_view verb, std::string_view particle);

// Whether a verb said for a task is a known task verb or close to one:
// "tidy", "clean up", "sort out"; not "get", "have" or "end".
bool names_a_known_task(const Lexicon& lexicon, std::string_view verb, std::string_view particle);

// A task's name as the reader names that task when a teacher says it:
// "clean living room" is "tidy living room", "clean up garage" is "tidy
// garage"; a name whose verb is known, or has no known verb close, is
// returned as given. For a name written elsewhere (a scenario's task, run
// --task) to find the task a teacher's words taught.
std::string task_name_as_read(const Lexicon& lexicon, std::string_view name);

// The step verb a verb said for a part of the task stands for, at a place
// of kind `place`; nullopt when it is known (a step verb, or one of
// `taught`, the verbs of the parts taught so far) or no known one is close.
std::optional<VerbTaken> known_step_verb(const Lexicon& lexicon, std::string_view verb, std::string_view particle,
                                         ObjectKind place, std::span<const std::string> taught);

// Whether a verb is one of the agent's own step verbs (clear, empty,
// store, unload) or one of `taught`, the verbs of the parts taught so far.
bool is_step_verb(std::string_view verb, std::span<const std::string> taught = {});

// English's reversative prefixes ("de", "un", "dis"): a verb WordNet
// lacks ("declutter") stands for the same stem with another of them that
// WordNet has ("unclutter": clear, rid of obstructions), which is
// returned; "" when WordNet has the verb itself or no such other.
std::string reversative_lemma(const Lexicon& lexicon, std::string_view verb);

// The step verb for taking everything from a place of this kind: a
// surface is cleared, a receptacle emptied.
std::string clearing_verb(ObjectKind place);

// "tidying", "clearing", "storing": the verb's -ing form, for read-backs.
std::string ing_form(std::string_view verb);

}  // namespace apprentice::language
