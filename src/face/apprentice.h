// apprentice.h: the library's one face. Every front end (the CLI's teach,
// run and experiment, the Python module, `apprentice serve`, the TidyBot
// benchmark, the example program) builds its agent here and nowhere else.
//
//   AgentSpec spec = default_agent_spec();       // a value; change what you need
//   spec.condition = "inst+search4";
//   spec.knowledge = "kitchen.sqlite";           // "" keeps nothing
//   Result<Scenario> world = load_scenario(data_dir() / "scenarios" / "tidy-kitchen.yaml");
//   Result<std::unique_ptr<AgentSession>> agent = make_agent_session(spec, *world);
//   Result<SessionReport> learned = (*agent)->learn(my_instructor);
//   Result<SessionReport> alone = (*agent)->perform("tidy kitchen");
//   std::string json = to_json(*alone);
//
// Ownership is stated per call. Errors are values (util/result.h); nothing
// here throws or aborts on bad input.
#pragma once

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "agent/condition.h"
#include "agent/report.h"
#include "instructor/dialogue.h"
#include "instructor/instructor.h"
#include "knowledge/store_access.h"
#include "util/result.h"
#include "world/scenario.h"

namespace apprentice {

struct Knowledge;
class LlmAdvisor;
namespace llm {
class LlmClient;
}

// The LLM, for the conditions that use one ("inst+llm", "search4+llm", ...).
struct LlmSpec {
  // The backend: "openai:http://127.0.0.1:8080/v1", "openai-chat:URL",
  // "llama:URL", "replay:FILE", "record:FILE,SPEC", "corpus:FILE" (see
  // llm/factory.h). Empty: $APPRENTICE_LLM, else none.
  std::string backend;
  std::string model;                   // empty: $OPENAI_MODEL, else none
  std::optional<std::string> api_key;  // unset: $OPENAI_API_KEY, else none
  std::optional<int> seed;             // sent with every request when set
  // Per request in all, and for connecting (unset: 30 s and 5 s).
  std::optional<std::chrono::milliseconds> timeout;
  std::optional<std::chrono::milliseconds> connect_timeout;
  // Ask the server once before the session, so that a dead one costs
  // seconds. When it does not answer: an error (kUnavailable), or with
  // `optional` the session goes on without the LLM (its rows degraded).
  bool check_first = true;
  bool optional = false;
  // The server is already known not to answer: never ask it.
  bool off = false;
  int goal_responses = 5;  // unique goal statements per query (the paper's is 3)
  // A program's own client instead of `backend`: called once per session.
  std::function<Result<std::unique_ptr<llm::LlmClient>>()> make_client;
  // Wraps the client made (to watch its queries, say); the wrapper must
  // answer as the client it wraps.
  std::function<std::unique_ptr<llm::LlmClient>(std::unique_ptr<llm::LlmClient>)> wrap;
};

// Everything an agent is built from. A plain value: copy it, change it.
struct AgentSpec {
  // The knowledge sources besides the instructor: "instruction",
  // "inst+search4", "search4+llm", "inst+llm", "inst+search2+llm",
  // "inst+search4+llm", "inst+search" (agent/condition.h).
  std::string condition = "inst+search4";
  // The condition as its parts instead (agent/condition.h): for the
  // settings no name stands for ("search4" alone, where the agent's
  // preference model supplies the goals).
  std::optional<Condition> condition_parts;
  // A person is teaching: the instructor answers whatever the condition
  // says (`apprentice teach`).
  bool instructed_always = false;
  std::string generalization = "full";  // rule generalization: "full" or "paper"
  bool use_rules = true;                // consult learned policy rules
  int max_actions_per_object = 30;
  int max_retries = 3;  // re-asks of a program (not a person) after an unusable reply
  // LLM goals: "all", "none", steps (drop,close,check,choose,reprompt) or
  // steps left out ("-choose") (agent/goal_repair.h); re-prompts per object;
  // offer goals that do not ground, as the paper did.
  std::string goal_repair = "all";
  int max_reprompts = 1;
  bool offer_ungrounded = false;
  // The knowledge store (an SQLite file or a postgresql:// URL), as --knowledge names it: loaded at the
  // start and extended as the agent learns. Empty: nothing is kept.
  std::string knowledge;
  StoreAccess store_access = StoreAccess::kReadWrite;
  // The household whose goal preferences and task structures the session
  // reads and writes (--household); the store's policy rules are shared by
  // all its households. 1 to 64 letters, digits, '-', '_' or '.'.
  std::string household = kDefaultHousehold;
  // This robot's name (--robot), saved with each goal and rule it learns
  // and said to the other robots ("Robot kitchen-2 just learned where the
  // ketchup goes."); empty: the host name (default_robot_name).
  std::string robot;
  // For a kind the household never taught, offer what the store's other
  // households chose (knowledge/fleet_prior.h); false leaves them out.
  bool fleet_prior = true;
  // Knowledge to start from instead of the store's; with a store it is
  // written into it first (experiment --knowledge-in with --knowledge-out).
  std::shared_ptr<const Knowledge> start_from;
  // The shipped data (prompt templates). Empty: data_dir().
  std::filesystem::path data;
  LlmSpec llm;
  // An advisor lent by the caller instead of one built from `llm` (several
  // sessions sharing one LLM's counts and breaker). Must outlive the session.
  LlmAdvisor* lent_advisor = nullptr;
};

AgentSpec default_agent_spec();

// What one learn() or perform() did.
struct SessionReport {
  AgentReport agent;  // per object; actions, search nodes, what was learned
  // The instructor left before the end (end of input, "quit", None from a
  // callback): what was learned is kept. `stop_reason` says how.
  bool stopped = false;
  std::string stop_reason;
  DialogueCounts counts;  // what the instructor said, as Table 3 counts it
  std::string transcript; // "Agent: ...\nInstructor: ...\n"
  State end;              // the world at the end
  // Against the scenario's intent, when it has one (`measured`).
  bool measured = false;
  int assertions_achieved = 0;
  int assertions_total = 0;
  double completion_rate = 0;  // percent
  int objects_done = 0;
  int objects_total = 0;
  // The LLM, when the session has one.
  int llm_calls = 0;
  long llm_tokens = 0;
  int llm_failures = 0;
  bool llm_stopped = false;  // not asked after repeated failures, or at all
  std::optional<int> llm_stopped_after_calls;
  std::string llm_stop_error;
  bool llm_ensemble = false;
  std::string llm_description;  // where its answers came from
  // The end of the session in English (language/narration.h): how much of
  // the intent holds, what is not done, and where the knowledge is kept.
  std::string summary;
};

// The report as JSON (keys in docs/python.md): counts, completion when
// measured, the objects, what needed help and what was carried over.
std::string to_json(const SessionReport& report);

// One agent with everything it uses. Owns the knowledge store, the LLM
// advisor (unless lent), the agent and a copy of the scenario. Not
// thread-safe: one call at a time.
class AgentSession {
 public:
  ~AgentSession();
  AgentSession(const AgentSession&) = delete;
  AgentSession& operator=(const AgentSession&) = delete;

  // Learns and performs the task the instructor teaches, on a fresh copy of
  // the world. `instructor` is borrowed for the call. The instructor
  // leaving is not an error (SessionReport::stopped). Errors: kIo/kDataLoss
  // when the store cannot be written; any other the agent's.
  Result<SessionReport> learn(Instructor& instructor);
  // Performs a learned task with learned knowledge alone, on a fresh copy
  // of `elsewhere` (borrowed for the call; null: this session's world).
  // Errors: kNotFound/kInvalidInput naming the tasks known when there is no
  // such task (an empty name: unless exactly one was learned).
  Result<SessionReport> perform(const std::string& task, const Scenario* elsewhere = nullptr);

  // What the agent knows now; valid until the next learn().
  const Knowledge& knowledge() const;
  const Scenario& scenario() const;
  // The knowledge store's file, when there is one.
  std::optional<std::filesystem::path> store_path() const;

  struct Parts;  // what the session owns; opaque (face/apprentice.cc)

 private:
  explicit AgentSession(std::unique_ptr<Parts> parts);
  friend Result<std::unique_ptr<AgentSession>> make_agent_session(const AgentSpec& spec, const Scenario& scenario);
  std::unique_ptr<Parts> parts_;
};

// Builds everything a session needs from `spec` in `scenario`'s world: opens
// and loads the store, makes and checks the LLM, the advisor and the agent.
// The session keeps a copy of `scenario`; the caller owns the result.
// Errors: kInvalidInput for a bad condition, generalization or goal-repair
// text, or an LLM condition without an LLM; the store's (kNotFound, kIo,
// kDataLoss); the LLM's (kUnavailable when its server does not answer and
// the LLM is not optional).
Result<std::unique_ptr<AgentSession>> make_agent_session(const AgentSpec& spec, const Scenario& scenario);

// The shipped data (domains, scenarios, prompt templates, the page): the
// folder $APPRENTICE_DATA names; else data/ of the checkout the running code
// was built in (found from the program or library file); else
// share/apprentice beside an installed one; else where the build was
// configured.
std::filesystem::path data_dir();

// Loads a world (a scenario file, docs/scenarios.md), whose `domain:` may
// name a shipped domain from any folder ("domain: kitchen"). Errors: those
// of load_scenario (world/scenario.h).
Result<Scenario> load_world(const std::filesystem::path& path);

// What an instructor of a program's own can say, in the words the agent
// reads best (the STARS instructor script's): "Tidy kitchen.", "Repeat the
// following tasks while an object is on the table.", "Clear an object that
// is on the table.", "If the object is a ketchup then the goal is that the
// object is in the fridge and the fridge is closed.", "Repeat.", "You are
// done.", "yes." / "no.".
namespace words {
std::string task_name(std::string_view name);
std::string repeat_while(const World& world, std::span<const ObjectId> places);
std::string subtask(std::string_view verb, const World& world, std::span<const ObjectId> places);
std::string goal(const World& world, ObjectId object, const Goal& goal);
std::string repeat();
std::string done();
std::string answer(bool yes);
}  // namespace words

// Planning and reading English without an agent: what `apprentice plan`
// and `apprentice interpret` print, for the CLI and the Python module alike
// (face/plan_and_interpret.cc). Each call takes the world read-only.

// The goal that stands for the whole task (`plan --goal intent`): every
// goal assertion of the scenario's intent.
inline constexpr std::string_view kIntentGoal = "intent";

// The goal `text` names in `scenario`'s world: PDDL, or kIntentGoal.
// Errors: kInvalidInput for English (told that `interpret` reads it) or a
// goal naming what the world lacks (with "did you mean ketchup1?").
Result<Goal> parse_goal_or_intent(const Scenario& scenario, const std::string& text);

struct PlanRequest {
  std::string goal;  // PDDL ("(and (in ketchup1 fridge1) (closed fridge1))"), or kIntentGoal
  // Iterative deepening to this depth (a shortest plan); unset: greedy
  // best-first search.
  std::optional<int> depth;
  std::optional<long> node_limit;      // stop after expanding this many nodes
  std::optional<double> time_limit_s;  // stop after this many seconds
  bool pruning = true;                 // ground only the objects relevant to the goal
  // Greedy search only: called about once a second after the first with a
  // line on its progress ("searching: 1200 nodes in 1.0 s (...)").
  std::function<void(const std::string&)> progress;
};

// What a search found, in the three forms `plan` prints.
struct PlanFound {
  bool solved = false;
  std::string status;                // "solved", "exhausted", "budget-exhausted", ...
  std::vector<std::string> actions;  // the plan in PDDL, one action each
  std::string text;  // `plan`: the numbered sentences ("1. Open the fridge.") and the search in one sentence
  std::string pddl;  // `plan --pddl`: one action a line, the search's figures on a ";;" line
  std::string json;  // `plan --json`
  // When no plan reaches the goal: why, in one sentence (the CLI's line
  // on stderr); empty otherwise.
  std::string why_not;
  // What relevance pruning did and why it is safe: sentences for a log.
  std::vector<std::string> notes;
};

// Searches from `scenario`'s state to `request.goal`. Not finding a plan is
// no error (PlanFound::solved). Errors: kInvalidInput for a goal that is not
// PDDL (English is told that `interpret` reads it) or names what the world
// lacks.
Result<PlanFound> plan(const Scenario& scenario, const PlanRequest& request);

// The kinds of question a teacher's reply is read at, in the one vocabulary
// of `interpret --asked`, Python's `interpret(asked=...)` and
// `Question.asked`, and docs/language.md: "task", "task-step",
// "subtask-end", "goal", "action", "yes-no", "which".
std::vector<std::string> question_kinds();
// The kind of question `question` is, in that vocabulary: a subtask's
// question about an object asks for its goal, without one whether the
// subtask is done; both confirmations are yes-no.
std::string question_kind(const Question& question);

// The question a reply answers (`interpret --asked`).
struct AskedQuestion {
  std::string kind;                   // one of question_kinds()
  std::optional<std::string> object;  // the thing asked about: an id ("mug2"), or a category (at `subtask`'s place)
  std::optional<std::string> subtask; // "clear"
  std::optional<std::string> recent;  // the place named last (an id)
  std::vector<std::string> choices;   // kind "which": the ids offered
};

// How a reply reads at a question.
struct ReplyReading {
  std::string reply, asked;
  // The reply's acts as the agent reads them, in order, joined by " ; ":
  // "goal (and (in ketchup1 fridge1) (closed fridge1))", "undo ; goal ...",
  // "unusable", ...
  std::string meaning;
  bool usable = false;   // no act is unusable or ambiguous
  std::string reason;    // unusable: why, in English
  std::string question;  // ambiguous: what the agent would ask
  std::vector<std::string> examples;  // unusable: replies that would work
  std::vector<std::string> notes;     // how words were taken: "I took "nah" as a no."
  std::vector<std::string> then;      // parts said for after this one: "the bucket"
  std::vector<std::string> goals_ahead;  // where things go, said after a part: for its first question
  std::string text;      // what `interpret --asked` prints
  std::string json;      // what `interpret --asked --json` prints
};

// Reads `reply` as a teacher's answer to `asked` in `scenario`'s world.
// Errors: kInvalidInput for a kind not in question_kinds(); kNotFound for
// an object, place or choice the world lacks.
Result<ReplyReading> interpret_reply(const Scenario& scenario, std::string_view reply, const AskedQuestion& asked);

// How a sentence reads as a goal or an action (`interpret "sentence"`).
struct SentenceReading {
  bool grounded = false;
  // The grammar does not cover it (the CLI's exit 2); `detail` says where.
  bool outside_grammar = false;
  std::string detail;
  std::string text;  // what `interpret` prints
  std::string json;  // what `interpret --json` prints
};

// Interprets `sentence` about `object` (an id, or a category at
// `subtask`'s place). Errors: kNotFound for an object the world lacks.
Result<SentenceReading> interpret_sentence(const Scenario& scenario, std::string_view sentence,
                                           const std::optional<std::string>& object,
                                           const std::optional<std::string>& subtask);

// Grounds every line of a JSON-lines corpus of LLM goal statements and
// returns the report `interpret --corpus` prints (JSON with `json`).
// Errors: the corpus file's (kNotFound, kInvalidInput with its line, kIo).
Result<std::string> interpret_corpus(const Scenario& scenario, const std::filesystem::path& corpus, bool json);

// Measures against a scenario's intent: its goal assertions that hold in
// `state`; the objects whose whole intended goal holds; the paper's
// completion rate in percent (100 when there are none).
int count_achieved_assertions(const Scenario& scenario, const State& state);
int count_objects_done(const Scenario& scenario, const State& state);
double completion_percent(int achieved, int total);

}  // namespace apprentice
