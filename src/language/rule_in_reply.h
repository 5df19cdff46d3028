// Whether a reply states a person's rule: the reading that decides, at any
// question, if "toys go in the storage box and fruits on the coffee table"
// is a rule to keep, rather than an answer the reply's own reading
// (read_reply) can use, and whether "dummy in the top drawer", asked about
// the pacifier, calls the thing asked about by another word.
//
// One reader for the whole program: the agent asks these, and the corpus
// tests read through them.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "language/grounding.h"
#include "language/reply.h"
#include "language/rule_reader.h"
#include "world/world.h"

namespace apprentice::language {

// "item", "thing", "stuff", ...: a head that names no class of its own ("heavy
// items" is a class of its modifiers).
bool is_general_head(std::string_view head);

// The one category `phrase` names here ("the ketchup", "plates"), by the
// reference's tiers; nullopt when none, or several.
std::optional<std::string> category_named(const Lexicon& lexicon, const World& world, std::string_view phrase);

// At a goal question, a reply that names the thing asked about by a word
// nothing here is called ("dummy in the top drawer", asked about the
// pacifier; `reply`, its own reading, could not use it): that word, else
// nullopt. Such a reply is never a rule.
std::optional<std::string> other_name_of_asked(const Grounder& grounder, const World& world, std::string_view text,
                                               const Reply& reply, const ReplyContext& context);

// The person's rule `text` states, where it states one that `reply` (its
// own reading at the question `context` asks) does not already take: a
// rule of two clauses or more, of "other", or of a class that is not the
// world's kinds said in the plural; nullopt else.
std::optional<RuleReading> rule_in_reply(const Grounder& grounder, const World& world, std::string_view text,
                                         const Reply& reply, const ReplyContext& context);

}  // namespace apprentice::language
