// Internal to the agent: the state of one run (learn or perform).
//
// Learning is a loop of steps (agent.cc, next_step): each step asks the
// curriculum (agent/curriculum.h, `Progress` here) what comes next and does
// that one thing: ask for the task, ask for its next step, work on the next
// object of the current subtask (its goal, known or asked for), or take the
// actions that achieve that object's goal. Everything a step decides lives
// in the curriculum, never in a caller's local variables, so that "undo" can
// put the progress, the knowledge and the world back as they were before
// the teacher's last lesson and the loop simply goes on from there.
#pragma once

#include <deque>
#include <functional>
#include <set>

#include "agent/actor.h"
#include "agent/agent.h"
#include "agent/conversation.h"
#include "agent/curriculum.h"
#include "agent/goal_sources.h"
#include "agent/lessons.h"
#include "agent/teacher_questions.h"
#include "knowledge/decision.h"
#include "language/reply.h"

namespace apprentice {

// `text` ending in a period, unless it ends with a quotation that has its
// own: "... last: \"Open the fridge.\"" (agent_dialogue.cc).
std::string with_period(std::string text);

class TaskLearningAgent::Session : private ActingHelp {
 public:
  Session(TaskLearningAgent& agent, Simulator& simulator, Dialogue* dialogue, bool learning);

  Result<AgentReport> learn_task();
  Result<AgentReport> perform_task(const TaskKnowledge& task);

 private:
  // Why a step stopped before its end (agent/flow.h).
  template <typename T>
  using Flow = apprentice::Flow<T>;
  using Step = Flow<void>;

  // How far the teaching has come (agent/curriculum.h): what a step reads and
  // changes, and what a lesson keeps.
  using Current = teaching::Current;
  using InProgress = teaching::InProgress;
  using Progress = teaching::Curriculum;
  // A reply usable at the question asked; none when a program's replies
  // could not be used within its attempts.
  struct Heard {
    std::optional<language::Reply> reply;
    std::string text;
    // The replies refused at this question before it, each as typed with
    // why it could not be used ("\"on the tabel\" (I do not know the word 'tabel')").
    std::vector<std::string> refused = {};
    // The reply was a person's rule, kept, said where the question was
    // where a thing goes: the rule may answer it (no reply then).
    bool rule_heard = false;
  };
  // Why a reply, though understood, does not answer this question; nullopt
  // if it does.
  using Accept = std::function<std::optional<std::string>(const language::Reply&)>;
  // What the agent itself can make of a reply the reader cannot use (from
  // what it knows), or nullopt.
  using Rescue = std::function<std::optional<language::Reply>(const std::string& text)>;

  // The steps (agent.cc).
  Step next_step();
  Step learn_task_name();
  Step learn_task_step();
  Step learn_subtask_end();
  Step start_known_subtask();
  Step start_subtask(const language::SubtaskNamed& named);
  void finish_subtask();
  Step start_object(ObjectId object);
  // Takes what other robots learned meanwhile into the agent's knowledge,
  // saying so once per kind (agent_news.cc).
  void take_news();
  Step achieve_current();
  std::optional<ObjectId> next_object(const Current& current) const;
  Status remember_task();
  // The report of a session whose task is finished: what the session and
  // the actor counted, with every object's report.
  AgentReport finished_report() const;

  // Conversation (agent_dialogue.cc).
  Question question(QuestionKind kind, std::string text, std::optional<ObjectId> object = std::nullopt,
                    std::optional<Goal> goal = std::nullopt, std::optional<Action> action = std::nullopt) const;
  language::ReplyContext context(language::Asked asked, std::optional<ObjectId> object = std::nullopt) const;
  Flow<Heard> converse(const Question& question, language::ReplyContext context, const Accept& accept,
                       const Rescue& rescue = nullptr);
  Flow<language::Reply> settle(const language::Ambiguous& ambiguous, const Question& asked,
                               language::ReplyContext& context, const std::string& text);
  Flow<bool> confirm(const Question& question);
  // Accepts a choice among `choices` ("the left one"); else asks which.
  static Accept chosen_among(std::vector<ObjectId> choices);
  Step obey(const language::Command& command, const Question& question, const language::ReplyContext& context);
  // The reason, and replies that would work: `examples` (the reader's, which
  // may fit the reply better), else the question's.
  void explain(const std::string& reason, const language::ReplyContext& context,
               std::vector<std::string> examples = {});
  // "forget X", as agent/forgetting.h decides it.
  Status forget(const std::string& what);
  void say(const std::string& statement, Voice voice = Voice::kNarration);
  // Executes `action` in the simulator; once it is done, the instructor
  // sees it (Instructor::observe).
  Status execute(const Action& action);
  bool person() const { return conversation_.with_person(); }

  // Lessons and undo (agent_undo.cc; the lessons themselves, with the
  // writes to the store they made, are agent/lessons.h). A lesson opens
  // only while a teacher teaches.
  void begin_lesson(const std::string& reply);
  // A person's rule, kept in the knowledge and the store, and in the
  // sources' said rules.
  Status store_class_rule(const ClassRule& rule);
  // The rules the goals induce, kept in the store with their evidence when
  // a session that learns ends (agent/class_rule_knowledge.h).
  Status keep_induced_rules_learned();
  Step undo();
  void put_world_back(const State& before, std::size_t history_size);
  // By a short search from the world now to `target`, the actions taken
  // added to `undoing`; false when none was found or one failed.
  bool back_to(const State& target, std::vector<Action>& undoing);
  // Back through the actions taken since `history_size`, latest first.
  bool back_step_by_step(const State& before, std::size_t history_size, std::vector<Action>& undoing);

  // Goals (agent_goals.cc).
  Flow<std::optional<Goal>> acquire_goal(ObjectId object, ObjectReport& report);
  Flow<std::optional<Goal>> goal_from_llm(ObjectId object, ObjectReport& report);
  Flow<std::optional<Goal>> goal_from_instructor(ObjectId object, ObjectReport& report);
  // Whether `reply` answers the goal question of `object`: nullopt when it
  // does (an ending or "leave it", its goal, or a goal for one thing still
  // to come, which is then `ahead`), else why not, in plain English.
  std::optional<std::string> why_not_a_goal_for(ObjectId object, const language::Reply& reply,
                                                std::optional<ObjectId>& ahead) const;
  // An ending said at the goal question of `object` ("I'm done"): with
  // other things of the part still to come, asked back by name ("There are
  // still 3 things on the table: ... Shall I leave them?"). nullopt when
  // nothing else is to come (the ending leaves this thing, as "leave it"
  // does); true when the teacher said to leave them (the part ends with
  // them where they are); false to go on asking about `object`.
  Flow<std::optional<bool>> ask_to_leave_the_rest(ObjectId object);
  // An ending or "leave it" said at a question about `object` (where it
  // goes, or a proposed goal): the thing is left where it is, and with an
  // ending and other things to come the rest of the part too, if the
  // teacher says so. false when the teacher said "no" to leaving the rest:
  // the question comes again.
  Flow<bool> leave_as_told(ObjectId object, const language::Finished& ended, const std::string& text,
                           ObjectReport& report);
  // Whether the teacher said to leave `object` where it is.
  bool was_left_as_told(ObjectId object) const;
  // Learns `goal` for `object`'s kind, under `key` (the kind's goal in the
  // subtask under way when none is given).
  Status learn_goal(ObjectId object, const Goal& goal, const std::string& source,
                    const std::optional<GoalKey>& key = std::nullopt);
  // A goal said at a question about the task's steps ("the notebook goes
  // on the bookshelf", after it was put in the filing cabinet): the kinds
  // whose goal it corrects, those learned in this task; none when no thing
  // of its kind was dealt with yet. With `properties` of `object` said
  // ("the clean diapers": {"clean"}), only the parts the things with them
  // were dealt with in.
  std::vector<GoalKey> goals_corrected_by(ObjectId object, const std::vector<std::string>& properties) const;
  // The key `thing` was dealt with under in this task (the part it was
  // cleared in), from its report; nullopt when it was not dealt with.
  std::optional<GoalKey> key_dealt_with(ObjectId thing) const;
  // The thing already dealt with whose goal `reply` corrects ("the notebook
  // goes on the bookshelf"), or nullopt.
  std::optional<ObjectId> thing_corrected(const language::Reply& reply) const;
  // Learns the corrected goal for each of those keys and moves the things
  // of the kind already dealt with to where it now says (agent_goals.cc).
  Status correct_goal(ObjectId object, const language::GoalGiven& said, const std::string& text);
  // Asks the LLM, the first time a thing needs it this session, for the
  // summary of what was taught and where each thing to place goes
  // (GoalSources::consult_llm). Nothing without an LLM in the condition.
  void consult_llm(ObjectId object);
  // Where rules said in this session apply: the task and the subtask under
  // way, and the kind of place cleared; empty fields before the task.
  GoalScope said_scope() const;
  // A person's rules (agent_person_rules.cc; whether a reply states one is
  // language/rule_in_reply.h, through Understanding).
  // Asks "By "dummy", do you mean the pacifier?"; on a yes, the reply read
  // again with the thing's own name in place of `word`; nullopt on a no.
  Flow<std::optional<language::Reply>> ask_other_name(const std::string& word, const std::string& text,
                                                      const Question& asked, const language::ReplyContext& context);
  // Keeps a rule the person said, and says what was understood of it and
  // what was not. A clause whose place fits look-alikes is asked which
  // first.
  Step hear_rule(language::RuleReading rule, const std::string& text);
  // Of the look-alikes a clause's place fits ("legos in the bin", with two
  // bins), the one a person chose when asked; nullopt with one place, or
  // with no person to ask.
  Flow<std::optional<ObjectId>> which_place_of(const language::RuleClause& clause);
  // Deciding where a thing goes that no goal is known for
  // (agent_decision.cc): the sources' proposals combined
  // (knowledge/decision.h); acted on alone when confident, else offered to
  // the teacher as one yes/no showing the evidence (a "no" is kept as an
  // exception for the kind). nullopt when nothing is likely enough, the
  // teacher refused every proposal, or, alone, the agent is in doubt (then
  // `report.note` says what it would have done and why it did not).
  Flow<std::optional<Goal>> goal_by_decision(ObjectId object, ObjectReport& report);
  // The things still to come, without a goal, that the decision would ask
  // about with the same destination at `policy`, like the same kinds taught
  // as `asked` shows for `object` (each with its goal there), as many as
  // are worth asking about with it: one yes/no may settle them all
  // (agent_decision.cc).
  std::vector<std::pair<ObjectId, Goal>> asked_together(ObjectId object, const Decision& asked, std::size_t places,
                                                        const DecisionPolicy& policy) const;
  // The goal a "yes" asked with another thing settled for `object`, said
  // back and learned; nullopt when none did.
  Flow<std::optional<Goal>> goal_settled(ObjectId object, ObjectReport& report);
  // Every source's proposals for `object` that the options ask
  // (GoalSources::proposals_for).
  std::vector<DestinationProposal> proposals_for(ObjectId object) const;
  // The teacher's answer to a proposed goal: yes, no, or, in place of no,
  // where the thing goes instead (then learned, and read back).
  struct ProposalAnswer {
    bool yes = false;
    std::optional<Goal> instead;
    // "I'm done", "leave it", said in place of yes or no, with its words.
    std::optional<language::Finished> ended = std::nullopt;
    std::string text = {};
  };
  Flow<ProposalAnswer> answer_to_proposal(const Question& asked, ObjectId object);
  // "the sweater goes on the low shelf", asked about the sock, for a thing
  // of another part of the task: asked about when its turn comes. (A thing
  // still to come in this part, "same again", "same as the hammer", a class
  // and "the rest" are read by language::read_reply, with what context()
  // gives it.)
  std::optional<language::Reply> goal_for_another(ObjectId object, const std::string& text) const;
  // The goals a reply gave other things along with the one for `about`
  // ("plates and forks go in the dishwasher"): those still to come in this
  // subtask are learned for their kinds, and said; the rest are asked
  // about in their turn.
  // A teacher's goal with the doors it opens closed after, unless the
  // teacher said to leave them open (closings_to_complete, agent/
  // goal_repair.h), for `about` and for each other thing it gave a goal.
  // `say_norm` is set the first time in the session that a closing came
  // from the norm alone: the read-back then adds closing_norm_note().
  language::GoalGiven with_doors_closed(ObjectId about, language::GoalGiven given, bool& say_norm);
  // Things already dealt with that it gives a goal they do not meet are
  // corrected (correct_goal), `text` being the teacher's words.
  Status learn_goals_of_others(ObjectId asked, ObjectId about, const language::GoalGiven& given,
                               const std::string& text, const std::string& source);
  GoalKey goal_key(ObjectId object) const;
  llm::TaskContext llm_context(ObjectId object) const;

  // What the actor (agent/actor.h) asks of the session (agent_actions.cc):
  // the LLM's and the teacher's next action, asked in the dialogue, and
  // the hands that carry an action out.
  Flow<std::optional<Action>> llm_action(InProgress& work, std::string& advice) override;
  Flow<std::optional<Action>> instructor_action(InProgress& work, std::string& advice) override;
  Status carry_out(const Action& action) override;
  void could_not_do(const Action& action) override;
  // Whom the actor may ask, and how far it goes alone, in this session.
  ActingPolicy acting_policy() const;

  const World& world() const { return simulator_.world(); }
  const Current& current() const { return *progress_.current; }
  std::string describe_object(ObjectId object) const;

  TaskLearningAgent& agent_;
  Simulator& simulator_;
  // The line to the teacher, with what was said ahead of its question and
  // the place named last (agent/conversation.h); no teacher when
  // performing alone.
  Conversation conversation_;
  bool learning_;
  Progress progress_;
  Lessons lessons_;  // the teacher's lessons this session, and what each wrote to the store
  // What the session reports beyond the actor's counts; objects come from progress_.
  AgentReport report_;
  std::vector<std::string> announced_;  // the kinds whose news was said, in this session
  // Acting toward each goal, with the counts of search and actions.
  Actor actor_;
  // Where a goal may come from when none is known (agent/goal_sources.h),
  // with the person's rules said, the LLM's preferences, and what the
  // teacher refused and settled. Constructed after the lessons: it renames
  // the agent's knowledge into this world's words when the session starts.
  GoalSources sources_;
  // The things an ending was asked back about ("Shall I leave them?"): a
  // second ending at the same thing, after a "no", leaves only that thing,
  // so that a teacher who keeps ending is never asked the same forever.
  std::set<ObjectId> asked_to_leave_the_rest_;
  // Whether closing_norm_note() was said this session.
  bool closing_norm_said_ = false;
  // The yes/no questions asked about where things go, in order: what "why
  // did you ask ...?" answers (agent/teacher_questions.h). What was asked
  // stays asked: an undo keeps them.
  std::vector<ProposalAsked> proposals_asked_;

  // The teacher's own questions are answered by agent/teacher_questions.h,
  // from what this reads; one-off actions ("close the top drawer") are done
  // by do_now (agent_dialogue.cc).
  TeachingSoFar so_far() const;
  void do_now(const std::vector<Action>& actions);
  // A standing wish about doors, a lesson of its own (undo takes it back).
  // `open` ("leave the washer open from now on"): the closing norm no
  // longer closes those places, and the goals learned that close them are
  // learned again leaving them open. Else ("this one stays closed"): they
  // are no longer left open, and the goals that put things in them are
  // learned again closing them.
  Status keep_doors(const std::vector<ObjectId>& places, const std::string& text, bool open);
};

}  // namespace apprentice
