// A teacher's everyday reply as words: the first step of read_reply
// (language/reply.h). Contractions are expanded, punctuation that separates
// clauses becomes the word ",", and names of the world that contain
// function words ("walk-in pantry", "half and half", "box of aluminum foil")
// become one word before anything treats "in", "and" or "of" as structure.
//
// The word classes below are closed lists of English function words; they
// say nothing about the world, which only language/mention.h consults.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "util/text.h"
#include "world/universe.h"

namespace apprentice::language {

// Lower-case words of a reply, at most kMaxSentenceWords of them (the rest
// is dropped): "That's all." -> {"that", "is", "all"}; "Put it in the
// fridge, then close it" -> {"put", "it", "in", "the", "fridge", ",", "then",
// "close", "it"}; "the fridge's door" -> {"the", "fridge", "door"}.
std::vector<std::string> reply_words(std::string_view text);

// Writes out shorthand said as whole words, in place: "pls" -> "please",
// "can't" -> "can not", "u" -> "you" (the table reply_words uses).
void expand_shorthand(std::vector<std::string>& words);

// Replaces every run of words that spells a category of `universe` whose
// name holds a function word (in, on, and, of, the, a, to, with...) by the
// category itself: {"the", "walk", "in", "pantry"} -> {"the",
// "walk-in-pantry"}; a plural last word counts ("jacks-in-the-box" aside,
// "walk in pantries" -> "walk-in-pantry").
// Then join_split_names and separate_listed_names.
void join_world_names(std::vector<std::string>& words, const Universe& universe);
// "t-shirt", typed as the world spells a kind: its words ({"t", "shirt"}),
// as a person's reply names every kind. (Not for the scripts' sentences,
// whose logical form keeps the category as written.)
void split_hyphenated_kinds(std::vector<std::string>& words, const Universe& universe);
// Three or more kinds of thing here named one after another without commas
// ("rake shovel hoe"), or two before "and" and a third ("rake shovel and
// hoe"), as typed in a hurry: a list, with the commas put in.
// Two words that make a name here ("paper plate") are never split.
void separate_listed_names(std::vector<std::string>& words, const Universe& universe);
// Two words that make one word of a name here, said apart: {"tool", "box"}
// -> {"toolbox"}, {"work", "benches"} -> {"workbenches"} (names of six
// letters or more, so that short words never run together).
void join_split_names(std::vector<std::string>& words, const Universe& universe);

// Removes `phrase` wherever it occurs as whole words; true if it did.
bool erase_phrase(std::vector<std::string>& words, const std::vector<std::string_view>& phrase);

// The words of a reply as one line to quote back: {"same", "as", "the",
// "hammer", ",", "and", ...} -> "same as the hammer, and ..." (a comma
// sticks to the word before it).
std::string quoted_words(const std::vector<std::string>& words);

// The words of a category or id, split on '-': "walk-in-pantry" -> {walk, in, pantry}.
std::vector<std::string> name_parts(std::string_view name);

// (A word's singular forms: singular_forms, util/text.h.)

// The properties of `thing` that `text` names as words ("the clean
// diapers": {"clean"}).
std::vector<std::string> properties_said(const Universe& universe, ObjectId thing, std::string_view text);

// --- Closed classes of English words ---------------------------------------
bool is_determiner(std::string_view w);       // the, a, this, my, all, every, ...
bool is_object_pronoun(std::string_view w);   // it, this, that, them, they, these, those
bool is_copula(std::string_view w);           // is, are, be, was, ...
bool is_auxiliary(std::string_view w);        // should, must, will, can, need, has, ...
bool is_negation(std::string_view w);         // not, never
bool is_generic_noun(std::string_view w);     // thing(s), stuff, everything, object(s), item(s), ...
bool is_door_word(std::string_view w);        // door, lid, cover, hatch
bool is_verb_of_going(std::string_view w);    // go, goes, belong, belongs, live, lives: where things go
bool is_state_word(std::string_view w);       // open, opened, closed, shut: a door's state
bool is_particle(std::string_view w);         // away, up, down, back, out, off, over, aside
bool is_filler(std::string_view w);           // please, ok, just, now, um, ...
bool is_clause_break(std::string_view w);     // ",", and, then, but, plus, also, ...
std::optional<std::size_t> ordinal(std::string_view w);  // first -> 0, second -> 1, 2nd -> 1

// The base form of a verb: the irregular forms people use around the house
// ("threw", "kept", "put", "went"), then regular suffixes checked against
// `known`, a predicate on base forms. "" if no base form is known.
template <typename Known>
std::string verb_base(std::string_view word, Known known);

// Irregular past forms and participles of household verbs; "" if none.
std::string irregular_verb_base(std::string_view word);
// Candidate base forms by regular English suffixes, most likely first:
// "stored" -> {"store", "stor"}, "dropping" -> {"drop", "dropp"}.
std::vector<std::string> regular_verb_bases(std::string_view word);

template <typename Known>
std::string verb_base(std::string_view word, Known known) {
  if (known(word)) return std::string(word);
  if (std::string base = irregular_verb_base(word); !base.empty()) return base;
  for (const std::string& base : regular_verb_bases(word))
    if (known(base)) return base;
  return "";
}

}  // namespace apprentice::language
