// A reply as dialogue acts (language/reply.h, read_acts): whatever the
// question, a reply may take back the last one ("oops scratch that"),
// correct it ("no wait, the bottom drawer": an undo and the answer the
// undone question should have had), ask something ("what's left?", "where
// is the soap?", "why did you close it?"), ask for a one-off action ("oh
// and close the top drawer"), or hold words that carry nothing here
// ("nah", "lol", "it's soaking"); the rest is the answer, read by the
// question's own reader (read_reply).
//
// The reply is cut at sentence and clause punctuation into segments. Each
// segment is one of: fillers only; an undo; a correction's marker ("no
// wait", "oops", "I meant"); a question of the teacher's; a one-off door
// action; or part of the answer. A door action is part of a goal when it
// is about the goal's own place ("in the hamper, close the lid").
#include <algorithm>
#include <deque>

#include "language/generation.h"
#include "language/narration.h"
#include "language/parser.h"
#include "language/reply_acts_parts.h"
#include "language/reply_reading.h"
#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language {
namespace acts {
namespace {

// "there by the X", "here next to the X": a spot said by another thing.
bool there_described(const Words& words) {
  for (std::size_t i = 0; i + 1 < words.size(); ++i)
    if (is_one_of(words[i], {"there", "here"}) &&
        is_one_of(words[i + 1], {"by", "near", "next", "beside", "behind", "under", "above", "below", "between", "against"}))
      return true;
  return false;
}

// "not in the drawer", "that's not where it goes", "it is not the shelf":
// a segment that only says what was wrong.
bool says_what_was_wrong(const Words& said) {
  Words words = without_interjections(said);
  if (words.empty()) return false;
  if (words.front() == "not") return true;
  if (words.size() > 2 && is_one_of(words[0], {"that", "it", "this"}) && words[1] == "is" && words[2] == "not")
    return true;
  return has(words, {"not", "where"});
}

// The places a reply says a thing does not go: "the bin, not the
// recycling", "in the cabinet and not in the drawer". Each segment that
// begins with "not" names them by the reference's own tiers, partial names
// and properties included ("not the top one" among drawers is not taken).
std::vector<ObjectId> places_said_not(const Grounder& grounder, const World& world, std::string_view text) {
  std::vector<ObjectId> out;
  ReferenceContext context{world, grounder.lexicon(), std::nullopt};
  context.partial_names = true;
  for (const Segment& s : segments(text)) {
    const Words words = without_leading_connectives(without_interjections(s.words));
    if (words.empty() || words.front() != "not") continue;
    Words phrase;
    for (std::size_t i = 1; i < words.size(); ++i)
      if (!is_determiner(words[i]) && !is_one_of(words[i], {"in", "on", "into", "onto", "inside"})) phrase.push_back(words[i]);
    if (phrase.empty()) continue;
    const auto candidates = candidates_for(NounPhrase{"", phrase}, Role::kPlace, context);
    if (const auto* found = std::get_if<CandidateSet>(&candidates))
      out.insert(out.end(), found->objects.begin(), found->objects.end());
  }
  return out;
}

// A close action for `place`, grounded; nullopt when it cannot be closed.
std::optional<Action> closing(const Grounder& grounder, const World& world, ObjectId place) {
  ActionCommand command;
  command.verb = ActionVerb::kClose;
  command.object = NounPhrase{"", {world.universe->name(place)}};
  Interpretation grounded = grounder.ground(command, world, std::nullopt);
  if (!grounded.ok()) return std::nullopt;
  return std::get<Action>(grounded.result);
}

// "the jeans go in the hamper and shut the washing machine door": a
// closing of a place no thing of the goal goes to is a one-off action, not
// part of the goal. The closings are taken out of the goal and returned.
// The script's grammar keeps its goals as they are (its sentences say
// exactly what the goal holds).
std::vector<Action> other_closings(const Grounder& grounder, const World& world, std::string_view text, Reply& reply) {
  auto* given = std::get_if<GoalGiven>(&reply);
  if (given == nullptr || parse(text).has_value()) return {};
  const Vocabulary& v = world.vocabulary;
  std::vector<ObjectId> to;
  auto collect = [&](const Goal& g) {
    for (const Literal& l : g.literals)
      if (l.positive && l.fact.arity == 2 && (l.fact.predicate == v.in || l.fact.predicate == v.on))
        to.push_back(l.fact.args[1]);
  };
  collect(given->goal);
  for (const Goal& g : given->others) collect(g);
  std::vector<ObjectId> closed;
  auto strip = [&](Goal& g) {
    std::erase_if(g.literals, [&](const Literal& l) {
      bool other = l.positive && l.fact.arity == 1 && l.fact.predicate == v.closed &&
                   std::find(to.begin(), to.end(), l.fact.args[0]) == to.end();
      if (other && std::find(closed.begin(), closed.end(), l.fact.args[0]) == closed.end()) closed.push_back(l.fact.args[0]);
      return other;
    });
  };
  strip(given->goal);
  for (Goal& g : given->others) strip(g);
  std::vector<Action> actions;
  for (ObjectId place : closed)
    if (auto a = closing(grounder, world, place)) actions.push_back(*a);
  return actions;
}

}  // namespace

namespace {

// A piece that asks to forget something ("and forget the paper rule", "ok
// can you forget that paper stuff rule"), after the words people open it
// with: the command; nullopt else.
std::optional<Command> forget_said(const Grounder& grounder, const World& world, const Words& said) {
  const Words words = without_fillers(without_leading_connectives(without_interjections(said)),
                                      ReplyVocabulary(*world.universe, grounder.lexicon()));
  if (words.empty() || words.front() != "forget") return std::nullopt;
  auto read = command(grounder, world, quoted_words(words));
  if (!read || read->kind != Command::Kind::kForget) return std::nullopt;
  return read;
}

// "pens aren't books", "they're clothes", "because it's trash": a reason
// said after the "too"s, which says no place and names nothing to move.
bool is_trailing_reason(const Words& piece) {
  if (piece.empty() || piece.size() > 6) return false;
  const bool says_why = std::any_of(piece.begin(), piece.end(), [](const std::string& w) {
    return is_copula(w) || is_negation(w) ||
           is_one_of(w, {"arent", "aren't", "isnt", "isn't", "because", "since", "cause", "cuz", "theyre", "they're",
                         "its", "it's"});
  });
  const bool says_where = std::any_of(piece.begin(), piece.end(), [](const std::string& w) {
    return is_one_of(w, {"in", "on", "into", "onto", "inside", "there", "go", "goes", "put", "too", "well"});
  });
  return says_why && !says_where;
}

}  // namespace

std::pair<std::string, std::vector<std::string>> without_trailing_toos(std::string_view answer) {
  Words words = reply_words(answer);
  // A reason after the "too"s ("and the pen too, pens aren't books") is
  // left out: the "too"s before it are the last clauses.
  for (std::size_t k = words.size(); k-- > 0;) {
    if (!is_one_of(words[k], {".", ";", "!", ","})) continue;
    Words last(words.begin() + static_cast<std::ptrdiff_t>(k + 1), words.end());
    while (!last.empty() && is_one_of(last.back(), {".", "!"})) last.pop_back();
    if (last.empty()) continue;
    if (is_trailing_reason(last) && k > 0 && words[k - 1] == "too") words.resize(k);
    break;
  }
  std::vector<std::string> toos;
  auto says_a_place = [](const Words& clause) {
    return std::any_of(clause.begin(), clause.end(), [](const std::string& w) {
      return is_one_of(w, {"in", "on", "into", "onto", "inside", "there", "it", "them", "go", "goes", "put"});
    });
  };
  // "no, top drawer. ruler and calculator too": a last sentence (or
  // comma's piece) of things said too, every one of them.
  for (std::size_t k = words.size(); k-- > 0;) {
    if (!is_one_of(words[k], {".", ";", "!", ","})) continue;
    Words last(words.begin() + static_cast<std::ptrdiff_t>(k + 1), words.end());
    while (!last.empty() && is_one_of(last.back(), {".", "!"})) last.pop_back();
    const bool too = !last.empty() && (last.back() == "too" || has(last, {"as", "well"}));
    if (!too || says_a_place(last) || last.size() > 8) break;
    std::erase_if(last, [](const std::string& w) { return is_one_of(w, {"too", "as", "well", "also"}); });
    Words item;
    bool short_items = true;
    auto flush = [&] {
      short_items = short_items && item.size() <= 3;
      if (!item.empty()) toos.push_back(quoted_words(item) + " too");
      item.clear();
    };
    for (const std::string& w : last)
      if (is_one_of(w, {",", "and"})) flush();
      else item.push_back(w);
    flush();
    if (toos.empty() || !short_items) {
      toos.clear();
      break;
    }
    return {quoted_words(Words(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(k))), toos};
  }
  std::size_t end = words.size();
  for (;;) {
    std::size_t cut = end;
    while (cut > 0 && !is_one_of(words[cut - 1], {",", "and"})) --cut;
    Words clause(words.begin() + static_cast<std::ptrdiff_t>(cut), words.begin() + static_cast<std::ptrdiff_t>(end));
    const bool too = !clause.empty() && (clause.back() == "too" || has(clause, {"as", "well"}));
    if (!too || says_a_place(clause) || clause.size() > 5) break;
    toos.insert(toos.begin(), quoted_words(clause));
    // The whole of it said too ("the milk as well", the rest of a yes).
    if (cut == 0) {
      end = 0;
      break;
    }
    end = cut - 1;
    while (end > 0 && is_one_of(words[end - 1], {",", "and"})) --end;
  }
  if (toos.empty()) return {std::string(answer), {}};
  return {quoted_words(Words(words.begin(), words.begin() + static_cast<std::ptrdiff_t>(end))), toos};
}

void add_the_same_for(const Grounder& grounder, const World& world, const ReplyContext& at,
                      const std::vector<std::string>& toos, GoalGiven& given) {
  if (!at.object) return;
  ReplyContext after = at;
  after.last_goal = ReplyContext::LastGoal{*at.object, given.goal};
  for (const std::string& too : toos) {
    const Reply same = read_reply(grounder, world, after, too);
    const auto* theirs = std::get_if<GoalGiven>(&same);
    if (theirs == nullptr) continue;
    auto add = [&](const Goal& g) {
      if (!(g == given.goal) && std::find(given.others.begin(), given.others.end(), g) == given.others.end())
        given.others.push_back(g);
    };
    add(theirs->goal);
    for (const Goal& g : theirs->others) add(g);
  }
}

namespace {

// The answer read without its "too"s, whose things then get the same goal;
// nullopt when the whole reading already gives others their goals, the
// answer says several places, or the "too"s add no goal. `notes` gets the
// notes of that reading; `whole_kept` is set when the whole reading stood
// for the words before the "too"s (its notes stand).
std::optional<Reply> with_the_toos(const Grounder& grounder, const World& world, const ReplyContext& at,
                                   const std::string& answer, const Reply& whole, std::vector<std::string>& notes,
                                   bool& whole_kept) {
  const auto* whole_goal = std::get_if<GoalGiven>(&whole);
  if (whole_goal != nullptr && !whole_goal->others.empty()) return std::nullopt;
  auto [before_toos, toos] = without_trailing_toos(answer);
  const Words before = reply_words(before_toos);
  const auto places_said = std::count_if(before.begin(), before.end(), [](const std::string& w) {
    return is_one_of(w, {"in", "on", "into", "onto", "inside"});
  });
  if (toos.empty() || trim(before_toos).empty() || places_said > 1) return std::nullopt;
  Reply first = read_answer(grounder, world, at, before_toos, notes);
  // ("thats just junk mail, recycle it. newspaper too": read alone, the
  // words before the "too"s keep the remark the whole reading left out;
  // that reading, which gave no other thing a goal, is theirs.)
  whole_kept = !std::holds_alternative<GoalGiven>(first) && whole_goal != nullptr;
  if (whole_kept) first = whole;
  auto* given = std::get_if<GoalGiven>(&first);
  if (given == nullptr || !given->others.empty()) return std::nullopt;
  add_the_same_for(grounder, world, at, toos, *given);
  if (given->others.empty()) return std::nullopt;
  return first;
}

}  // namespace

ReplyActs read(const Grounder& grounder, const World& world, const ReplyContext& context, std::string_view text) {
  ReplyActs out;
  Reply whole = read_reply(grounder, world, context, text);
  // A command of the whole reply, and at an action or which question the
  // question's own reading, stand as they are.
  if (std::holds_alternative<Command>(whole) || context.asked == Asked::kWhich ||
      (context.asked == Asked::kAction && usable(whole))) {
    out.acts.push_back(std::move(whole));
    return out;
  }
  if (auto steps = several_steps(grounder, world, context, text, whole, out.goals_ahead)) {
    out.acts.push_back(std::move(steps->first));
    out.then = std::move(steps->second);
    return out;
  }
  out.goals_ahead.clear();
  std::vector<Segment> parts = segments(text);
  // "crayons go in the left bin no wait, the right one": a strong marker
  // said last in a piece begins the next one, which corrects it.
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    Words& words = parts[i].words;
    for (std::size_t k = std::min<std::size_t>(3, words.size() > 0 ? words.size() - 1 : 0); k > 0; --k) {
      const Words tail(words.end() - static_cast<std::ptrdiff_t>(k), words.end());
      const Marker m = marker(tail);
      // ("ketchup in the pantry actually, we keep it there": "actually"
      // last is no correction; "oh wait, close it" has nothing before it.)
      if (m.length != k || !m.strong || tail.front() == "actually") continue;
      const bool said_before = std::any_of(words.begin(), words.end() - static_cast<std::ptrdiff_t>(k),
                                           [](const std::string& w) { return !is_marker(w) && !is_interjection(w); });
      if (!said_before) continue;
      Words& next = parts[i + 1].words;
      next.insert(next.begin(), tail.begin(), tail.end());
      parts[i + 1].text = quoted_words(next);
      words.erase(words.end() - static_cast<std::ptrdiff_t>(k), words.end());
      parts[i].text = quoted_words(words);
      break;
    }
  }
  std::vector<Reply> before, after;  // undos; questions and one-off actions
  std::vector<const Segment*> answer, doors;
  std::deque<Segment> repaired;  // what follows a marker inside a segment
  std::vector<std::vector<Action>> door_actions;
  std::vector<bool> door_first;  // said before the answer
  std::vector<Reply> first_doors;  // one-off actions said before the answer, done first
  // Corrections of a read-back are made at the next goal question.
  const bool corrects = context.asked == Asked::kGoal;
  Marker lead;
  bool lead_in_answer = false;
  bool weak = false;  // "nah", "no": a filler unless the answer corrects
  std::string marker_said;
  bool correcting = false;
  bool undo_words = false;  // an undo was said with the word "undo"
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Segment& s = parts[i];
    // ("yeah. oh and close the cabinet": at a yes/no question a yes said
    // with a word that is also a filler is the answer.)
    const bool yes_or_no_said = context.asked == Asked::kYesNo && answer_prefix(s.words);
    if (without_interjections(s.words).empty() && answer.empty() && before.empty() && !yes_or_no_said) continue;
    // "fair enough", "got it", "makes sense": an acknowledgement, no answer.
    if (is_one_of(quoted_words(without_interjections(s.words)), {"fair enough", "got it", "makes sense", "sounds good",
                                                                   "no problem", "all good", "my bad"}))
      continue;
    // "forget it. floor next": never mind, before more; no "forget" command.
    const Words said = without_interjections(s.words);
    if (parts.size() > 1 && (said == Words{"forget", "it"} || said == Words{"forget", "that"} ||
                             said == Words{"never", "mind"} || said == Words{"nevermind"})) {
      out.notes.push_back("I took " + quote(s.text) + " as never mind.");
      continue;
    }
    if (corrects && answer.empty() && before.empty()) {
      Marker m = marker(s.words);
      if (m.length > 0 && m.length >= s.words.size()) {
        correcting = correcting || m.strong;
        weak = weak || !m.strong;
        marker_said = quoted_words(s.words);
        continue;
      }
    }
    if (int n = undos(s.words); n > 0 && answer.empty()) {
      // "go back one, that was wrong": one undo; "undo undo", "undo, undo":
      // two, one per "undo" said; "wait that's wrong, undo that": one, the
      // same undo said twice.
      const bool said_undo = std::find(s.words.begin(), s.words.end(), "undo") != s.words.end();
      if (said_undo && !undo_words) before.clear();
      if (before.empty() || said_undo)
        for (int k = 0; k < n; ++k) before.push_back(Command{Command::Kind::kUndo, "", {}, {}});
      undo_words = undo_words || said_undo;
      correcting = true;
      continue;
    }
    // "put it back, shelf was right": the place confirms the undo.
    if (!before.empty() && confirms_the_old_place(s.words)) continue;
    // "put it back, it leaks": why, said after an undo, answers nothing.
    if (!before.empty() && answer.empty() && is_remark(grounder, world, s.words)) {
      out.notes.push_back("I took " + quote(s.text) + " as a reason, not an instruction.");
      continue;
    }
    if (ends_session(s.words, context.asked)) {
      out.acts = {Command{Command::Kind::kQuit, "", {}, {}}};
      return out;
    }
    if (asks_for_help(s.words)) {
      after.push_back(Command{Command::Kind::kHelp, "", {}, {}});
      continue;
    }
    if (auto q = question(grounder, world, s.words)) {
      after.push_back(*q);
      continue;
    }
    // "leave the washer open from now on", "i want it left open": a door
    // the teacher wants left open, opened now if it is closed. ("filing
    // cabinet, and leave that open from now on": "that" is the place the
    // answer before it names.)
    ReplyContext wish = context;
    if (!answer.empty() && std::find(s.words.begin(), s.words.end(), "open") != s.words.end())
      if (auto place = destination(world, read_reply(grounder, world, context, joined(answer)))) wish.recent_place = place;
    if (auto openings = doors_left_open(grounder, world, wish, s.words)) {
      Command keep{Command::Kind::kDo, s.text, {}, {}};
      for (const Action& opening : *openings) {
        const ObjectId place = opening.arguments()[0];
        keep.left_open.push_back(place);
        if (world.state.holds(Fact(world.vocabulary.closed, {place}))) keep.actions.push_back(opening);
      }
      after.push_back(std::move(keep));
      continue;
    }
    // "this one stays closed, the cat gets in there": a door the teacher
    // wants closed from now on, closed now if it is open. ("this one" is
    // the place the reply closed or named before it.)
    if (!door_actions.empty() && !door_actions.back().empty() && !door_actions.back().front().arguments().empty())
      wish.recent_place = door_actions.back().front().arguments()[0];
    if (auto closings = doors_kept_closed(grounder, world, wish, s.words)) {
      Command keep{Command::Kind::kDo, s.text, {}, {}};
      for (const Action& closing : *closings) {
        const ObjectId place = closing.arguments()[0];
        keep.kept_closed.push_back(place);
        // ("shut the locker. this one stays closed": closed once.)
        const bool said_before = std::any_of(door_actions.begin(), door_actions.end(), [&](const std::vector<Action>& a) {
          return std::find(a.begin(), a.end(), closing) != a.end();
        });
        if (!said_before && !world.state.holds(Fact(world.vocabulary.closed, {place}))) keep.actions.push_back(closing);
      }
      after.push_back(std::move(keep));
      continue;
    }
    // "no!! blue bin w the balls. and forget the paper rule", "ok can you
    // forget that paper stuff rule": forgetting, said along with more.
    if (auto forget = forget_said(grounder, world, s.words)) {
      after.push_back(*forget);
      continue;
    }
    if (context.asked != Asked::kAction)
      if (auto actions = door_action(grounder, world, context, s.words)) {
        door_first.push_back(answer.empty());
        doors.push_back(&s);
        door_actions.push_back(*actions);
        continue;
      }
    if (!answer.empty() && what_someone_did_from(s.words) < s.words.size()) {
      out.notes.push_back("I took " + quote(s.text) + " as a remark.");
      continue;
    }
    // "leave the sweater, I'll wear it", "close the cabinet, it's been
    // open all day": why, told after an answer or an action.
    const bool about_a_thing = context.asked == Asked::kGoal || context.asked == Asked::kYesNo;
    if (((about_a_thing && !answer.empty()) || !doors.empty()) && says_why(grounder, world, s.words)) {
      out.notes.push_back("I took " + quote(s.text) + " as a reason, not an instruction.");
      continue;
    }
    if (auto kept = about_a_thing ? without_reason(grounder, world, s.words) : std::nullopt) {
      const Words reason(s.words.begin() + static_cast<std::ptrdiff_t>(kept->size()), s.words.end());
      out.notes.push_back("I took " + quote(quoted_words(reason)) + " as a reason, not an instruction.");
      repaired.push_back({quoted_words(*kept), *kept});
      answer.push_back(&repaired.back());
      continue;
    }
    // "bottom drawer. no wait, top", "in the fridge, sorry, the pantry":
    // the reply corrects itself, and what it said before the marker is
    // not part of the answer. A marker said last corrects nothing.
    if (!answer.empty() || !doors.empty()) {
      Marker m = marker(s.words);
      // ("top drawer. sorry, typo": a marker with nothing after it but
      // words that carry nothing corrects nothing.)
      const bool said_after =
          m.length < s.words.size() || std::any_of(parts.begin() + static_cast<std::ptrdiff_t>(i) + 1, parts.end(),
                                                   [](const Segment& later) {
                                                     return !without_interjections(later.words).empty();
                                                   });
      if (m.length > 0 && m.strong && said_after) {
        // ("first shut the top drawer... no wait it's already shut": the
        // action said before the marker is taken back too.)
        std::vector<const Segment*> left_out = doors;
        left_out.insert(left_out.end(), answer.begin(), answer.end());
        out.notes.push_back("I left out " + quote(joined(left_out)) + ": you corrected it.");
        doors.clear();
        door_actions.clear();
        door_first.clear();
        answer.clear();
        lead_in_answer = false;
        if (m.length < s.words.size()) {
          Words rest(s.words.begin() + static_cast<std::ptrdiff_t>(m.length), s.words.end());
          repaired.push_back({quoted_words(rest), rest});
          answer.push_back(&repaired.back());
        }
        continue;
      }
    }
    if (corrects && answer.empty()) {
      Marker m = marker(s.words);
      if (m.length > 0 && m.length < s.words.size()) {
        lead = m;
        lead_in_answer = true;
        correcting = correcting || m.strong;
        weak = weak || !m.strong;
      }
    }
    answer.push_back(&s);
  }
  // What the answer is read as: after an undo or a strong marker, the
  // answer the undone question should have had (about the thing of the
  // last goal); a weak marker ("nah") corrects only when the answer names
  // that thing or says "not" its place.
  ReplyContext at = context;
  std::string answer_text = joined(answer);
  if (lead_in_answer && !answer.empty()) {
    const Words& first = answer.front()->words;
    std::size_t cut = std::min(lead.length, first.size());
    marker_said = quoted_words(Words(first.begin(), first.begin() + static_cast<std::ptrdiff_t>(cut)));
    answer_text = quoted_words(Words(first.begin() + static_cast<std::ptrdiff_t>(cut), first.end()));
    if (answer.size() > 1)
      answer_text += ", " + joined(std::vector<const Segment*>(answer.begin() + 1, answer.end()));
  }
  const Words all = reply_words(answer_text);
  auto names = [&](ObjectId thing) {
    for (const std::string& part : name_parts(world.universe->info(thing).category))
      if (std::find(all.begin(), all.end(), part) != all.end() || std::find(all.begin(), all.end(), part + "s") != all.end())
        return true;
    return false;
  };
  // "no, TOP drawer", just after "So the pen goes in the bottom drawer":
  // the answer names a look-alike of the last goal's place by a property
  // that place has not.
  auto names_a_look_alike_of = [&](ObjectId place) {
    const ObjectInfo& info = world.universe->info(place);
    if (!names(place)) return false;
    for (ObjectId other : world.universe->with_category(info.category)) {
      if (other == place) continue;
      for (const std::string& property : world.universe->info(other).properties)
        if (std::find(all.begin(), all.end(), property) != all.end() &&
            std::find(info.properties.begin(), info.properties.end(), property) == info.properties.end())
          return true;
    }
    return false;
  };
  if (weak && !correcting && context.last_goal && !answer.empty()) {
    // It names the last thing, says "not" the last place, or names a
    // look-alike of the last place.
    bool not_there = std::find(all.begin(), all.end(), "not") != all.end();
    const std::optional<ObjectId> last_place = destination(world, GoalGiven{context.last_goal->goal});
    correcting = names(context.last_goal->object) || not_there || (last_place && names_a_look_alike_of(*last_place));
  }
  // "hang on, the printer paper goes in the cupboard" (asked about the
  // printer paper, the last goal the dictionary's): a marker before an
  // answer that names the thing asked about, and says nothing of the last
  // goal's thing or place and no undo, corrects nothing.
  if (correcting && context.asked == Asked::kGoal && context.last_goal && before.empty() && !answer.empty()) {
    const ObjectId last = context.last_goal->object;
    const std::optional<ObjectId> last_place = destination(world, GoalGiven{context.last_goal->goal});
    const bool names_asked =
        context.object && world.universe->info(*context.object).category != world.universe->info(last).category &&
        names(*context.object);
    // ("actually the gloves should hang on the right hook", asked about
    // the hose after the twine: about a third thing already dealt with,
    // which the reply's reading takes as its own correction.)
    // (By the last word of its name, "the gloves" for gardening gloves:
    // the words of "half and half" are no name alone.)
    bool names_another = false;
    for (ObjectId o : context.dealt_with) {
      const std::string& kind = world.universe->info(o).category;
      const std::string head = name_parts(kind).back();
      const bool said = std::find(all.begin(), all.end(), head) != all.end() ||
                        std::find(all.begin(), all.end(), head + "s") != all.end();
      if (kind != world.universe->info(last).category &&
          (!context.object || kind != world.universe->info(*context.object).category) && said)
        names_another = true;
    }
    // ("wait the washer fluid is not recycling, its full! bottom shelf",
    // asked about the washer fluid after the water bottle went in the
    // recycling bin: the place said "not" of the thing asked about is no
    // correction of the last goal.)
    auto first_of = [&](auto&& is) {
      return static_cast<std::size_t>(std::find_if(all.begin(), all.end(), is) - all.begin());
    };
    const std::size_t negation = first_of([](const std::string& w) { return is_negation(w) || is_one_of(w, {"isnt", "arent"}); });
    const std::vector<std::string> asked_parts = context.object ? name_parts(world.universe->info(*context.object).category)
                                                                : std::vector<std::string>{};
    const bool not_of_asked = names_asked && negation < all.size() &&
                              first_of([&](const std::string& w) {
                                return std::find(asked_parts.begin(), asked_parts.end(), w) != asked_parts.end();
                              }) < negation;
    if ((names_asked || names_another) && !names(last) && (not_of_asked || !(last_place && names(*last_place)))) {
      correcting = false;
      weak = names_asked;  // the marker said of a third thing needs no note
    }
  }
  if (weak && !correcting && !marker_said.empty()) out.notes.push_back("I took " + quote(marker_said) + " as a filler.");
  // A marker before a question or a one-off action alone ("wait, where's
  // the ketchup?", "hang on, close the fridge first") takes nothing back.
  // ("it's sticking out", said with the closing, is a remark, no answer.)
  const bool answers = std::any_of(answer.begin(), answer.end(), [&](const Segment* a) {
    return !is_remark(grounder, world, a->words);
  });
  if (correcting && before.empty() && !answers && (!after.empty() || !doors.empty())) correcting = false;
  if (correcting && context.last_goal && context.asked == Asked::kGoal && before.empty())
    before.push_back(Command{Command::Kind::kUndo, "", {}, {}});
  if (correcting && context.last_goal && context.asked == Asked::kGoal) {
    at.object = context.last_goal->object;
    at.recent_place = destination(world, GoalGiven{context.last_goal->goal});
    // "not in the drawer", "that's not where the rake goes" say what was
    // wrong, not what is right.
    std::vector<std::string> kept;
    for (const Segment& s : segments(answer_text))
      if (!says_what_was_wrong(s.words)) kept.push_back(s.text);
    answer_text = join(kept, ", ");
    out.after_undo = answer_text;
  }
  const std::vector<ObjectId> not_there = places_said_not(grounder, world, answer_text);
  // Remarks ("it's soaking", "kids") are dropped when the rest is whole.
  Reply reply = Unusable{};
  bool answered = !trim(answer_text).empty();
  const std::size_t notes_before_answer = out.notes.size();
  if (answered) {
    reply = read_answer(grounder, world, at, answer_text, out.notes);
    if (!usable(reply) && answer.size() > 1) {
      std::vector<const Segment*> kept;
      std::vector<std::string> dropped;
      for (const Segment* s : answer) {
        if (is_remark(grounder, world, s->words)) dropped.push_back(s->text);
        else kept.push_back(s);
      }
      if (!dropped.empty() && !kept.empty()) {
        Reply retry = read_answer(grounder, world, at, joined(kept), out.notes);
        if (usable(retry)) {
          reply = retry;
          for (const std::string& d : dropped) out.notes.push_back("I took " + quote(d) + " as a remark.");
        }
      }
    }
  }
  // "pan in the sink, knife too", read whole as the pan's goal alone: the
  // answer read without the "too"s, which then give their things the same
  // goal. ("milk and cream too" read whole is both; "combs in the jar,
  // brushes in the drawer, scissors too" says several places, and which
  // one "too" repeats is not guessed.)
  if (answered && at.asked == Asked::kGoal && at.object) {
    std::vector<std::string> notes;
    bool whole_kept = false;
    if (auto with_toos = with_the_toos(grounder, world, at, answer_text, reply, notes, whole_kept)) {
      reply = std::move(*with_toos);
      if (!whole_kept) {
        out.notes.resize(notes_before_answer);
        out.notes.insert(out.notes.end(), notes.begin(), notes.end());
      }
    }
  }
  // "it goes in the bin, not in the recycling bin", where the recycling
  // bin is the only bin: the place the answer was read as is the one the
  // person ruled out; asked back, never acted on.
  if (const std::optional<ObjectId> to = destination(world, reply);
      to && std::find(not_there.begin(), not_there.end(), *to) != not_there.end())
    reply = Unusable{"You said not " + spoken_name(world, *to) + ", but that is where I took it to go. Which place do you mean?",
                     example_replies(world, at), std::nullopt, {}};
  // A door action about the goal's own place is part of the goal.
  std::optional<ObjectId> goes_to = destination(world, reply);
  for (std::size_t i = 0; i < doors.size(); ++i) {
    const std::vector<Action>& actions = door_actions[i];
    std::vector<Action> actions_said = door_actions[i];
    // "close the doors", "lids on": the doors of the place the goal names.
    if (goes_to && actions_said.size() > 1 && is_door_word(doors[i]->words.back()))
      std::erase_if(actions_said, [&](const Action& a) { return a.arguments().empty() || a.arguments()[0] != *goes_to; });
    if (actions_said.empty()) actions_said = actions;
    bool own = goes_to && actions_said.size() == 1 && world.domain->actions[actions_said.front().schema].name != "open" &&
               actions_said.front().arguments().size() == 1 && actions_said.front().arguments()[0] == *goes_to;
    if (own) {
      std::string door_text = actions_said.size() < actions.size() ? "close it" : doors[i]->text;
      Reply with = read_answer(grounder, world, at, answer_text + ", " + door_text, out.notes);
      if (usable(with)) {
        reply = with;
        answer_text += ", " + door_text;
        if (correcting) out.after_undo = answer_text;
        continue;
      }
    }
    if (door_first[i]) first_doors.push_back(Command{Command::Kind::kDo, "", {}, actions});
    else after.insert(after.begin(), Command{Command::Kind::kDo, "", {}, actions});
  }
  // "over there by the thingamajig", "here next to the sink": "there" is
  // a spot said by another thing, not the place named last; asked back.
  if (answered && usable(reply) && there_described(reply_words(answer_text)))
    reply = Unusable{"I can't tell which place \"there\" is. Please name the place.", example_replies(world, at), std::nullopt, {}};
  if (answered) {
    std::vector<Action> closings = other_closings(grounder, world, answer_text, reply);
    if (!closings.empty()) after.push_back(Command{Command::Kind::kDo, "", {}, closings});
  }
  // "why are you asking, it's a needle": a "why" said with an answer is
  // the teacher's remark, not a question to answer; unless it asks about
  // something done ("yes. hang on why'd you put the candy bar in the
  // cooler").
  if (answered && usable(reply))
    std::erase_if(after, [](const Reply& r) {
      const auto* c = std::get_if<Command>(&r);
      if (c == nullptr || c->kind != Command::Kind::kWhy) return false;
      const Words asked = split_words(c->argument);
      return !(has(asked, {"did", "you"}) || has(asked, {"you", "put"}) || has(asked, {"you", "throw"}) ||
               has(asked, {"you", "move"}) || has(asked, {"whyd", "you"}) || has(asked, {"why'd", "you"}));
    });
  for (Reply& r : before) out.acts.push_back(std::move(r));
  for (Reply& r : first_doors) out.acts.push_back(std::move(r));
  // Without an answer, the undo, the question or the action stands alone;
  // with nothing at all, the whole reply's reading (why it is unusable).
  if (answered && (usable(reply) || (before.empty() && after.empty() && first_doors.empty()))) out.acts.push_back(reply);
  for (Reply& r : after) out.acts.push_back(std::move(r));
  if (out.acts.empty()) out.acts.push_back(answered ? reply : whole);
  return out;
}

}  // namespace acts

namespace {

// Whether `lower` has `phrase` at `at` as whole words.
bool phrase_at(const std::string& lower, std::size_t at, std::string_view phrase) {
  auto word_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '\''; };
  if (lower.compare(at, phrase.size(), phrase) != 0) return false;
  if (at > 0 && word_char(lower[at - 1])) return false;
  const std::size_t end = at + phrase.size();
  return end == lower.size() || !word_char(lower[end]);
}

// "just for tonight put the shaker in the locker", "the blanket goes on the
// sofa, its cold tonight": `text` without the words that say a placement
// holds this time only, and those words; nullopt when it has none.
std::optional<std::pair<std::string, std::string>> without_this_time_only(std::string_view text) {
  // Longest first, so that "just for tonight" goes whole.
  static constexpr std::array<std::string_view, 16> kOneOff = {
      "just for tonight", "just for today", "just for now", "just this once", "just this time", "for tonight",
      "for today", "for the night", "for now", "this once", "this time", "until tomorrow", "till tomorrow",
      "tonight", "for a bit", "for a while"};
  std::string out(text);
  std::string said;
  for (std::string_view phrase : kOneOff) {
    std::string lower = to_lower(out);
    for (std::size_t at = lower.find(phrase); at != std::string::npos; at = lower.find(phrase, at + 1)) {
      if (!phrase_at(lower, at, phrase)) continue;
      if (said.empty()) said = out.substr(at, phrase.size());
      out.erase(at, phrase.size());
      lower.erase(at, phrase.size());
    }
  }
  if (said.empty()) return std::nullopt;
  return std::pair{out, said};
}

}  // namespace

ReplyActs read_acts(const Grounder& grounder, const World& world, const ReplyContext& context, std::string_view text) {
  // A goal said for this time only is read without the words that say so,
  // and marked; they change no other reading (a task "for today" is the
  // task).
  const auto one_off = context.asked == Asked::kTask ? std::nullopt : without_this_time_only(text);
  ReplyActs out = acts::read(grounder, world, context, one_off ? std::string_view(one_off->first) : text);
  bool for_now = false;
  if (one_off)
    for (Reply& act : out.acts)
      if (auto* given = std::get_if<GoalGiven>(&act)) for_now = given->this_time_only = true;
  if (for_now) out.notes.push_back("I took " + acts::quote(one_off->second) + " as this time only.");
  if (one_off && !for_now) out = acts::read(grounder, world, context, text);
  // A task or part named with another verb than the agent's says how it
  // was taken ("I took \"clean up\" as tidying.").
  for (const Reply& act : out.acts) {
    if (const auto* task = std::get_if<TaskNamed>(&act); task && !task->note.empty()) out.notes.push_back(task->note);
    if (const auto* part = std::get_if<SubtaskNamed>(&act); part && !part->note.empty()) out.notes.push_back(part->note);
  }
  return out;
}

}  // namespace apprentice::language
