// Goals said by reference to other things (language/reply_reading.h), read
// at a goal question when the question's own reader could not use the
// reply: leaving the thing where it is ("skip it"), the goal given last
// ("socks too", "same again", "ditto"), the goal of a kind taught before
// ("same as the hammer", "goes with the blocks"), a goal for another thing
// still to come ("the jeans go in the hamper", asked about the towel), and
// a class or the rest of the things ("clothes go in the hamper", "the rest
// on the floor", "everything else goes in the hamper except the hair
// dryer"), each read back with the things it covers.
//
// What the dialogue knows comes in ReplyContext (last_goal, still_to_come,
// goal_of_kind); without it such replies are asked back.
#include <algorithm>

#include "language/narration.h"
#include "language/reply_reading.h"
#include "language/same_as.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language {
namespace {

using Words = std::vector<std::string>;

// The goal with `from` replaced by `to` wherever it is an argument.
Goal for_thing(const Goal& goal, ObjectId from, ObjectId to) {
  std::vector<Literal> literals = goal.literals;
  for (Literal& l : literals)
    for (std::size_t i = 0; i < l.fact.arity; ++i)
      if (l.fact.args[i] == from) l.fact.args[i] = to;
  return Goal(std::move(literals));
}

const std::string& kind_of(const World& world, ObjectId id) { return world.universe->info(id).category; }

// The things a phrase may name, by part of their names too ("fork" for
// the metal fork); none when it names nothing here.
std::vector<ObjectId> may_name(const Grounder& grounder, const World& world, const std::string& phrase) {
  Words words = split_words(to_lower(phrase));
  std::erase_if(words, [](const std::string& w) { return is_determiner(w) || w == "other"; });
  if (words.empty()) return {};
  ReferenceContext context{world, grounder.lexicon(), std::nullopt};
  context.partial_names = true;
  auto found = candidates_for(NounPhrase{"", words}, Role::kItem, context);
  const auto* set = std::get_if<CandidateSet>(&found);
  return set == nullptr ? std::vector<ObjectId>() : set->objects;
}

bool to_come(const ReplyContext& c, ObjectId o) {
  return std::find(c.still_to_come.begin(), c.still_to_come.end(), o) != c.still_to_come.end();
}

// Who of a kind gets a goal: the thing asked about, else the first of
// that kind still to come.
std::optional<ObjectId> who_of_kind(const World& world, const ReplyContext& c, const std::string& kind) {
  if (c.object && kind_of(world, *c.object) == kind) return c.object;
  for (ObjectId o : c.still_to_come)
    if (kind_of(world, o) == kind) return o;
  return std::nullopt;
}

Reply asked_back(const World& world, const ReplyContext& c, const std::string& reason) {
  std::string where = c.object ? " Where should " + spoken_name(world, *c.object) + " go?" : "";
  return Unusable{reason + where, example_replies(world, c), std::nullopt};
}

// The words of "leave it be", "leave them where they are", "leave it
// out": where the thing is, or that it stays.
bool says_where_it_is(std::string_view w) {
  return is_one_of(w, {"it", "that", "this", "one", "them", "those", "alone", "be", "there", "where", "is", "are",
                       "they", "as", "for", "here", "put", "was", "the", "way", "out"});
}

// "done", "skip it", "leave it be", "it stays where it is".
bool leaves_it_alone(const Words& said) {
  Words words;
  for (const std::string& w : said)
    if (w != "," && !is_filler(w)) words.push_back(w);
  if (words.empty()) return false;
  static const std::vector<std::vector<std::string_view>> kWhole = {
      {"done"}, {"nowhere"}, {"nothing"}, {"pass"}, {"it", "stays"}, {"it", "can", "stay"},
      {"do", "not", "move", "it"}, {"it", "is", "fine"}, {"it", "is", "fine", "there"}, {"it", "stays", "there"},
      {"it", "can", "stay", "there"}, {"it", "is", "fine", "where", "it", "is"}, {"it", "stays", "where", "it", "is"}};
  for (const auto& phrase : kWhole)
    if (std::equal(words.begin(), words.end(), phrase.begin(), phrase.end())) return true;
  if (!is_one_of(words.front(), {"leave", "skip", "ignore", "keep"})) return false;
  return std::all_of(words.begin() + 1, words.end(), [](const std::string& w) { return says_where_it_is(w); });
}

// "leave the sweater", "leave the notebook out", asked about the sweater or
// the notebook: the thing asked about named, and left alone.
bool leaves_the_thing_alone(const Grounder& grounder, const World& world, const ReplyContext& c, const Words& said) {
  if (!c.object) return false;
  Words words;
  for (const std::string& w : said)
    if (w != "," && !is_filler(w)) words.push_back(w);
  if (words.size() < 2 || !is_one_of(words.front(), {"leave", "skip", "ignore"})) return false;
  Words named;
  for (auto w = words.begin() + 1; w != words.end(); ++w)
    if (!says_where_it_is(*w) && !is_determiner(*w)) named.push_back(*w);
  // ("leave the mug in the sink" says where it goes.)
  const bool says_a_place = std::any_of(named.begin(), named.end(), [](const std::string& w) {
    return is_one_of(w, {"in", "on", "into", "onto", "inside", "with", "by", "next", "under", "open", "closed", "shut"});
  });
  if (named.empty() || says_a_place) return false;
  const std::vector<ObjectId> things = may_name(grounder, world, join(named, " "));
  const std::string& kind = kind_of(world, *c.object);
  return std::any_of(things.begin(), things.end(), [&](ObjectId o) { return kind_of(world, o) == kind; });
}

// The goal given last, for `object`.
std::optional<Goal> given_last_for(const ReplyContext& c, ObjectId object) {
  if (!c.last_goal) return std::nullopt;
  return for_thing(c.last_goal->goal, c.last_goal->object, object);
}

// "socks too", "same again", "milk and cream too".
std::optional<Reply> goal_given_last(const Grounder& grounder, const World& world, const ReplyContext& c,
                                     const std::string& named, std::string_view text) {
  if (!c.object) return std::nullopt;
  std::vector<std::string> phrases(1);
  for (const std::string& word : split_words(named)) {
    if (word == "and" || word == ",") phrases.emplace_back();
    else phrases.back() += (phrases.back().empty() ? "" : " ") + word;
  }
  std::vector<ObjectId> to;
  for (const std::string& phrase : phrases) {
    if (phrase.empty()) continue;
    std::vector<ObjectId> things = may_name(grounder, world, phrase);
    std::optional<ObjectId> who;
    const std::string& kind = kind_of(world, *c.object);
    if (std::any_of(things.begin(), things.end(), [&](ObjectId o) { return kind_of(world, o) == kind; })) who = c.object;
    for (ObjectId o : things)
      if (!who && to_come(c, o)) who = o;
    // "and the pen too, pens aren't books": a thing already dealt with, its
    // goal corrected (the agent moves it).
    for (ObjectId o : things)
      if (!who && std::find(c.dealt_with.begin(), c.dealt_with.end(), o) != c.dealt_with.end()) who = o;
    if (!who) return std::nullopt;
    if (std::find(to.begin(), to.end(), *who) == to.end()) to.push_back(*who);
  }
  if (to.empty()) to = {*c.object};
  std::stable_partition(to.begin(), to.end(), [&](ObjectId o) { return o == *c.object; });
  if (!c.last_goal)
    return asked_back(world, c,
                      "I have not put anything away yet, so I do not know what \"" + std::string(trim(text)) +
                          "\" refers to.");
  GoalGiven given;
  for (std::size_t i = 0; i < to.size(); ++i) {
    Goal goal = *given_last_for(c, to[i]);
    if (i == 0) given.goal = std::move(goal);
    else given.others.push_back(std::move(goal));
  }
  return given;
}

// "same as the soda can, and shut the drawer".
std::optional<Reply> goal_like_another(const Grounder& grounder, const World& world, const ReplyContext& c,
                                       const SameAs& same) {
  if (!c.object) return std::nullopt;
  std::vector<std::string> kinds;
  for (ObjectId o : may_name(grounder, world, same.other))
    if (std::find(kinds.begin(), kinds.end(), kind_of(world, o)) == kinds.end()) kinds.push_back(kind_of(world, o));
  if (kinds.size() > 1 && c.last_goal)  // "the other mug": the one given last
    if (std::find(kinds.begin(), kinds.end(), kind_of(world, c.last_goal->object)) != kinds.end())
      kinds = {kind_of(world, c.last_goal->object)};
  // A kind not here, taught before and named whole ("like the coloring
  // book", where only a picture book is here): that kind, not a thing here
  // named by part of it.
  Words words = split_words(to_lower(same.other));
  std::erase_if(words, [](const std::string& w) { return is_determiner(w); });
  const std::string key = join(words, "-");
  for (std::string form : singular_forms(key))
    if (std::find(kinds.begin(), kinds.end(), form) == kinds.end() && world.universe->with_category(form).empty() &&
        c.goal_of_kind && c.goal_of_kind(form, *c.object))
      kinds = {form};
  if (kinds.size() != 1) return std::nullopt;
  // "the highlighter goes with the pens", asked about the folder: what
  // becomes of another thing, not of this one.
  if (!same.subject.empty() && !is_one_of(same.subject, {"it", "this", "that", "this one", "that one", "they", "these"})) {
    const std::vector<ObjectId> said = may_name(grounder, world, same.subject);
    if (!said.empty() && std::none_of(said.begin(), said.end(), [&](ObjectId o) {
          return kind_of(world, o) == kind_of(world, *c.object);
        }))
      return asked_back(world, c, "That says what becomes of " + spoken_name(world, said.front()) +
                                      ", but I asked about " + spoken_name_and_location(world, *c.object) + ".");
  }
  std::optional<Goal> goal;
  if (c.goal_of_kind) goal = c.goal_of_kind(kinds.front(), *c.object);
  if (!goal && c.last_goal && kind_of(world, c.last_goal->object) == kinds.front()) goal = given_last_for(c, *c.object);
  if (!goal)
    return asked_back(world, c, "I have not learned where " + kind_goes(kinds.front()) + " yet.");
  if (!same.more.empty()) {
    // The rest adds to that goal, read after the placement it makes, so
    // that "the drawer" and "it" are that place.
    std::optional<ObjectId> place;
    for (const Literal& l : goal->literals)
      if ((l.fact.predicate == world.vocabulary.in || l.fact.predicate == world.vocabulary.on) && l.fact.arity == 2 &&
          l.fact.args[0] == *c.object)
        place = l.fact.args[1];
    if (!place) return std::nullopt;
    std::string placed = "put it " + std::string(relation_word(world, *place)) + " " + spoken_name(world, *place) +
                         ", " + same.more;
    Reply rest = read_reply_plain(grounder, world, c, placed);
    const auto* given = std::get_if<GoalGiven>(&rest);
    if (given == nullptr) return std::nullopt;
    // What the rest says wins over what was copied ("same as the stapler
    // but leave the drawer open": open, though the stapler's closes it),
    // and is not said twice.
    std::vector<Literal> literals = goal->literals;
    for (const Literal& said : given->goal.literals) {
      std::erase_if(literals, [&](const Literal& copied) { return copied.fact == said.fact; });
      literals.push_back(said);
    }
    goal = Goal(std::move(literals));
  }
  return GoalGiven{*goal};
}

// "the jeans go in the hamper", asked about the towel: the goal of the one
// other thing it names, when that is still to come.
std::optional<Reply> goal_for_another(const Grounder& grounder, const World& world, const ReplyContext& c,
                                      std::string_view text) {
  if (!c.object) return std::nullopt;
  ReplyContext none = c;
  none.object.reset();
  Reply reply = read_reply_plain(grounder, world, none, text);
  const auto* given = std::get_if<GoalGiven>(&reply);
  if (given == nullptr) return std::nullopt;
  std::vector<ObjectId> items;
  for (ObjectId o : given->goal.objects())
    if (world.universe->info(o).kind == ObjectKind::kItem) items.push_back(o);
  if (items.size() != 1 || items.front() == *c.object || !to_come(c, items.front())) return std::nullopt;
  return reply;
}

// Where a phrase is in the words: its first word's index, and its length
// with the determiners and "of" before it ("all of the clothes").
std::optional<std::pair<std::size_t, std::size_t>> span_of(const Words& words, const Words& phrase) {
  if (phrase.empty() || phrase.size() > words.size()) return std::nullopt;
  for (std::size_t i = 0; i + phrase.size() <= words.size(); ++i) {
    if (!std::equal(phrase.begin(), phrase.end(), words.begin() + static_cast<std::ptrdiff_t>(i))) continue;
    std::size_t start = i;
    while (start > 0 && (is_determiner(words[start - 1]) || words[start - 1] == "of")) --start;
    return std::pair{start, i + phrase.size() - start};
  }
  return std::nullopt;
}

// The words a reply names the rest by: "the rest", "everything else",
// "the others", "everything", "all of it", "all of them".
// "left shelf with the others", "next to the rest": said after a word of
// place, the phrase says where the thing goes (by the others already
// there), not which things go.
std::optional<Words> rest_phrase(const Words& words) {
  for (const Words& phrase : {Words{"everything", "else"}, Words{"anything", "else"}, Words{"all", "the", "rest"},
                              Words{"the", "rest"}, Words{"rest"}, Words{"the", "others"}, Words{"everything"},
                              Words{"all", "of", "it"}, Words{"all", "of", "them"}}) {
    const auto at = span_of(words, phrase);
    if (!at) continue;
    const std::size_t start = at->first;
    if (start > 0 && is_one_of(words[start - 1], {"with", "w", "beside", "by", "near", "alongside", "among", "to"}))
      continue;
    return phrase;
  }
  return std::nullopt;
}

// The kinds the words after "except" or "but not" name: left out of a class.
std::vector<std::string> excepted(const Grounder& grounder, const World& world, Words& words) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < words.size(); ++i) {
    bool except = words[i] == "except" || (words[i] == "but" && i + 1 < words.size() && words[i + 1] == "not") ||
                  (words[i] == "apart" && i + 1 < words.size() && words[i + 1] == "from");
    if (!except) continue;
    std::size_t start = i + (words[i] == "except" ? 1 : 2);
    std::size_t end = start;
    while (end < words.size() && words[end] != ",") ++end;
    std::string phrase = join(Words(words.begin() + static_cast<std::ptrdiff_t>(start),
                                    words.begin() + static_cast<std::ptrdiff_t>(end)), " ");
    for (ObjectId o : may_name(grounder, world, phrase)) out.push_back(kind_of(world, o));
    words.erase(words.begin() + static_cast<std::ptrdiff_t>(i), words.begin() + static_cast<std::ptrdiff_t>(end));
    break;
  }
  return out;
}

// "clothes go in the hamper", "the rest on the floor": the class or the
// rest of the things, each read as the thing asked about would be.
std::optional<Reply> goal_for_a_class(const Grounder& grounder, const World& world, const ReplyContext& c,
                                      std::string_view text, const Reply& first) {
  if (!c.object) return std::nullopt;
  Words words = reply_words(text);
  join_world_names(words, *world.universe);
  std::vector<std::string> left_out = excepted(grounder, world, words);
  std::vector<ObjectId> members;
  std::pair<std::size_t, std::size_t> span{0, 0};
  bool spanned = false;
  if (auto rest = rest_phrase(words)) {
    if (auto at = span_of(words, *rest)) span = *at, spanned = true;
    // The rest: what is still to come and not named elsewhere in the reply.
    // A kind is named when the last word of its name is said ("the hair
    // dryer", "dryers").
    auto is_named = [&](ObjectId o) {
      std::vector<std::string> parts = name_parts(kind_of(world, o));
      return std::any_of(words.begin(), words.end(), [&](const std::string& w) {
        std::vector<std::string> forms = singular_forms(w);
        return std::find(forms.begin(), forms.end(), parts.back()) != forms.end() || w == kind_of(world, o);
      });
    };
    if (!is_named(*c.object)) members.push_back(*c.object);
    for (ObjectId o : c.still_to_come)
      if (o != *c.object && !is_named(o)) members.push_back(o);
    // "the rest of the tools": the rest of a class.
    std::size_t after = span.first + span.second;
    if (spanned && after + 1 < words.size() && words[after] == "of") {
      Words of;
      std::size_t end = after + 1;
      for (; end < words.size() && words[end] != "," && !is_copula(words[end]) &&
             !is_one_of(words[end], {"go", "goes", "in", "on", "into", "onto", "can", "should"});
           ++end)
        if (!is_determiner(words[end])) of.push_back(words[end]);
      std::vector<std::string> all;
      for (ObjectId o : members) all.push_back(kind_of(world, o));
      std::vector<std::string> kinds = grounder.lexicon().kinds_under(join(of, " "), all);
      std::erase_if(members, [&](ObjectId o) {
        return std::find(kinds.begin(), kinds.end(), kind_of(world, o)) == kinds.end();
      });
      span.second = end - span.first;
    }
    // "everything in this crate", "everything else on the shelf": only
    // what is at that place ("this" and "that" one: where the thing asked
    // about is).
    after = span.first + span.second;
    if (spanned && after + 1 < words.size() && is_one_of(words[after], {"in", "on", "from", "inside"})) {
      std::size_t k = after + 1;
      std::string determiner;
      if (is_determiner(words[k])) determiner = words[k++];
      // Where they are, not where they go: a verb follows ("the rest on the
      // floor" says where the rest go).
      if (k + 1 < words.size() && is_one_of(words[k + 1], {"go", "goes", "belong", "belongs", "can", "should", "need",
                                                            "needs", "is", "are", "gets", "get", "will"})) {
        std::vector<ObjectId> places;
        std::optional<ObjectId> asked_at = place_of(world, *c.object);
        if (is_one_of(determiner, {"this", "that"}) && asked_at) {
          places.push_back(*asked_at);
        } else {
          for (ObjectId p = 0; p < world.universe->size(); ++p) {
            if (world.universe->info(p).kind == ObjectKind::kItem) continue;
            std::vector<std::string> forms = singular_forms(words[k]);
            if (std::find(forms.begin(), forms.end(), name_parts(world.universe->info(p).category).back()) != forms.end())
              places.push_back(p);
          }
        }
        if (!places.empty()) {
          std::erase_if(members, [&](ObjectId o) {
            std::optional<ObjectId> at = place_of(world, o);
            return !at || std::find(places.begin(), places.end(), *at) == places.end();
          });
          span.second = k + 1 - span.first;
        }
      }
    }
  } else {
    const auto* unusable = std::get_if<Unusable>(&first);
    if (unusable == nullptr || !unusable->failure || unusable->failure->kind != FailureKind::kUngroundedObject)
      return std::nullopt;
    // The class's words; a modifier the world does not model ("dirty
    // clothes", "small hand tools") narrows nothing.
    Words phrase = split_words(unusable->failure->detail);
    std::vector<std::string> kinds;
    std::vector<std::string> all;
    for (ObjectId o : world.universe->of_kind(ObjectKind::kItem))
      if (std::find(all.begin(), all.end(), kind_of(world, o)) == all.end()) all.push_back(kind_of(world, o));
    for (std::size_t drop = 0; drop < phrase.size() && kinds.empty(); ++drop) {
      Words head(phrase.begin() + static_cast<std::ptrdiff_t>(drop), phrase.end());
      kinds = grounder.lexicon().kinds_under(join(head, " "), all);
      if (!kinds.empty())
        if (auto at = span_of(words, head)) span = *at, spanned = true;
    }
    if (kinds.empty() || !spanned) return std::nullopt;
    std::stable_partition(kinds.begin(), kinds.end(), [&](const std::string& k) { return k == kind_of(world, *c.object); });
    for (const std::string& kind : kinds)
      if (auto who = who_of_kind(world, c, kind)) members.push_back(*who);
  }
  std::erase_if(members, [&](ObjectId o) {
    return std::find(left_out.begin(), left_out.end(), kind_of(world, o)) != left_out.end();
  });
  if (members.empty() || !spanned) return std::nullopt;
  // Read with the first member's name for the class's words, then the
  // same goal for each other member.
  const ObjectId lead = members.front();
  Words said(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(span.first));
  for (const std::string& w : split_words(spoken_category(kind_of(world, lead)))) said.push_back(w);
  said.insert(said.end(), words.begin() + static_cast<std::ptrdiff_t>(span.first + span.second), words.end());
  Reply reply = read_reply_plain(grounder, world, c, quoted_words(said));
  auto* given = std::get_if<GoalGiven>(&reply);
  if (given == nullptr) return std::nullopt;
  const Goal* lead_goal = &given->goal;
  for (const Goal& g : given->others) {
    std::vector<ObjectId> in_it = g.objects();
    if (std::find(in_it.begin(), in_it.end(), lead) != in_it.end()) lead_goal = &g;
  }
  std::vector<ObjectId> mentioned = lead_goal->objects();
  if (std::find(mentioned.begin(), mentioned.end(), lead) == mentioned.end()) return std::nullopt;
  Goal common = *lead_goal;
  for (ObjectId o : members)
    if (o != lead) given->others.push_back(for_thing(common, lead, o));
  return reply;
}

}  // namespace

std::optional<Reply> read_goal_with_rest(const Grounder& grounder, const World& world, const ReplyContext& context,
                                         std::string_view text, const Reply& first) {
  if (context.still_to_come.empty() || !rest_phrase(reply_words(text))) return std::nullopt;
  return goal_for_a_class(grounder, world, context, text, first);
}

std::optional<Reply> read_goal_by_others(const Grounder& grounder, const World& world, const ReplyContext& context,
                                         std::string_view text, const Reply& first) {
  Words words = reply_words(text);
  if (leaves_it_alone(words) || leaves_the_thing_alone(grounder, world, context, words)) return Finished{};
  // "I'm done", "that's it", "we're done here": an ending, which the
  // question pending decides the meaning of (language/reply.h, Finished).
  if (ReplyInput in(grounder, world, context, words); says_only_an_ending(words, in)) return Finished{true};
  if (auto again = read_same_again(text)) return goal_given_last(grounder, world, context, *again, text);
  SameAs same = read_same_as(text);
  if (!same.other.empty())
    if (auto like = goal_like_another(grounder, world, context, same)) return like;
  if (auto another = goal_for_another(grounder, world, context, text)) return another;
  return goal_for_a_class(grounder, world, context, text, first);
}

}  // namespace apprentice::language
