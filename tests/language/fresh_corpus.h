// The scorer of the fresh reply corpora (tests/language/fresh/setN, their
// FORMAT.md): each line's reply is read with the product's reader
// (language::read_reply) in the context the line describes, and the reading
// is compared with the labelled meaning, a list of acts.
//
// A line is one of three outcomes:
// - understood as meant: the reading's acts are the label's (goals compared
//   thing by thing, as a set, within each run of goal acts);
// - asked back (a safe miss): the reader asked back or refused (Ambiguous,
//   Unusable), or its acts are the label's with some goals for other things
//   left out, which the agent asks about when it comes to them;
// - acted on wrongly: any other usable reading. A label `ask-back` is met
//   by a reader that asks back.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "language/grounding.h"
#include "language/reply.h"
#include "world/scenario.h"

namespace apprentice::language::fresh {

enum class Outcome { kMeant, kAskedBack, kWrong };
std::string_view to_string(Outcome outcome);

// One labelled reply (FORMAT.md).
struct Line {
  std::string file;  // "bathroom.jsonl:17"
  std::string id;
  std::string world;  // the world file named by the line
  std::string asked;
  std::optional<std::string> about;
  nlohmann::json context;  // an object, possibly empty
  std::string reply;
  nlohmann::json meaning;  // a non-empty array of acts
};

// Every line of every *.jsonl in `folder`, in file order; a line that does
// not parse or lacks a field is an error naming it.
struct Corpus {
  std::vector<Line> lines;
  std::vector<std::string> errors;
};
Corpus read_corpus(const std::filesystem::path& folder);

// The world a line names: the folder's own YAML, else a shipped scenario
// (data/scenarios/<name>). Loaded once per file.
class Worlds {
 public:
  explicit Worlds(std::filesystem::path folder) : folder_(std::move(folder)) {}
  const Scenario* get(const std::string& world_file, std::string& error);

 private:
  std::filesystem::path folder_;
  std::map<std::string, Scenario> loaded_;
};

// The acts of a label or a reading, each as a line of text in one
// vocabulary ("goal towel in hamper1 closed=null", "undo", "task tidy
// bathroom"), a run of goal acts as one sorted set of such lines.
using Acts = std::vector<std::vector<std::string>>;

struct Scored {
  Outcome outcome = Outcome::kWrong;
  Acts label;
  Acts reading;
  std::string reply_line;  // format_reply of what was read
  std::string error;       // the label names nothing in the world, an unknown act
  double seconds = 0;      // how long read_acts took
};

// What the line's context gives the reader (ReplyContext), built in its world.
ReplyContext context_of(const Line& line, const World& world, std::string& error);

// Reads one line and scores it.
Scored score(const Grounder& grounder, const World& world, const Line& line);

// Counts per kind of act (a line counts once under each kind its label
// holds) and per question.
struct Tally {
  int meant = 0;
  int asked_back = 0;
  int wrong = 0;
  int total() const { return meant + asked_back + wrong; }
};
struct Report {
  std::map<std::string, Tally> by_act;
  std::map<std::string, Tally> by_asked;
  Tally overall;
};
void add(Report& report, const Line& line, Outcome outcome);
// The tables, as printed by the test and copied into docs/language.md.
std::string format_report(const Report& report);

}  // namespace apprentice::language::fresh
