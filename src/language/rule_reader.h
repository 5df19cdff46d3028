// Reading a person's rule: where kinds of things go, said in one sentence
// or a few, at any question, before the task or after it.
//
//   "Put toys in the storage box and fruits on the coffee table."
//   "heavy items on the left shelf, light ones on the right"
//   "books and magazines on the coffee table, stuffed animals on the sofa,
//    and other toys in the storage box"   ("other": what the rest leave)
//   "by the way, shoes always go on the rack"
//
// The reader finds each clause: a class of things and a place of this
// world. It keeps every clause it understood, and returns the parts it
// could not read by name, so that one unknown phrase never sinks the rest.
// It says what the words say: whether a thing fits a class ("is a Rubik's
// cube a toy?") is for the knowledge that holds classes (the agent's
// preferences), never decided here.
//
// A reply that names only particular things of the world ("the sweater
// goes in the basket", "it goes in the basket") is not a rule: read_reply
// reads it as a goal.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "language/lexicon.h"
#include "language/logical_form.h"
#include "world/world.h"

namespace apprentice::language {

// A class of things as said: "heavy items", "light-colored clothes",
// "other toys", "everything else".
struct RuleClass {
  std::string phrase;  // lower case, without determiners and "other": "heavy items", "toys", "" for everything
  std::string head;    // the head noun, in its base form: "item", "toy", "clothes"; "" for everything
  std::vector<std::string> modifiers;  // the words before the head ("heavy"), and after it ("made of metal": "metal")
  // "other toys", "the rest", "everything else": the things of this class
  // the other clauses leave.
  bool rest = false;
};

// One clause: these classes go at these places.
struct RuleClause {
  std::string text;               // the clause as said: "other toys in the storage box"
  std::vector<RuleClass> classes;  // "books and magazines": two; never empty
  Relation relation = Relation::kIn;  // as said; a place of the other kind is taken all the same
  // The place meant: one, or several when the words fit several places of
  // this world ("the drawers", "the shelf" among three shelves).
  std::vector<ObjectId> places;
  // A particular thing of this world named instead of a class ("the
  // sweater in the basket"): its id. Such a clause is a plain goal.
  std::optional<ObjectId> thing;
};

struct RuleReading {
  std::vector<RuleClause> clauses;  // in the order said
  // Parts of the text that are not clauses it could read, as said:
  // "electronics in the attic" (no such place), "stuff".
  std::vector<std::string> not_understood;

  // Whether some clause is about a class, not only particular things.
  bool has_class_clause() const;
};

// The rule `text` states in `world`, or nullopt when the text states no
// clause at all (a plain answer such as "in the basket" or "yes"). Never
// throws. `lexicon` gives base forms of words and relations between place
// names ("the bin" for the trash can), as in the rest of the reader;
// `object_of_interest` is what "it" and "this" name; `there`, the place
// "there" names (the place named last).
std::optional<RuleReading> read_rule(const World& world, const Lexicon& lexicon, std::string_view text,
                                     std::optional<ObjectId> object_of_interest = std::nullopt,
                                     std::optional<ObjectId> there = std::nullopt);

// The class as a person says it: "other toys", "heavy items", "everything else".
std::string say_rule_class(const RuleClass& rule_class);
// What the reader understood, in English: "So toys go in the storage box,
// and fruits go on the coffee table." Clauses with several places say
// them with "or".
std::string read_back_rule(const World& world, const RuleReading& reading);
// A clause whose place fits look-alikes ("legos in the bin", where a left
// and a right bin stand): which of them, as a question ("Which bin do legos
// go in: the left bin or the right bin?"); nullopt when the clause names one
// place, or places of different kinds.
std::optional<std::string> ask_which_place_of(const World& world, const RuleClause& clause);

}  // namespace apprentice::language
