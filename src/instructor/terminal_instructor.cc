#include "instructor/terminal_instructor.h"

#include <unistd.h>

#include <cstdlib>
#include <ostream>

#include <editline/readline.h>

#include "util/text.h"

namespace apprentice {

TerminalInstructor::TerminalInstructor(std::FILE* in, std::ostream& out)
    : in_(in), out_(out), interactive_(isatty(fileno(in)) != 0) {
  if (interactive_) {
    rl_instream = in_;
    using_history();
  }
}

TerminalInstructor::~TerminalInstructor() = default;

Result<std::string> TerminalInstructor::read_line(const char* prompt) {
  if (interactive_) {
    out_.flush();
    char* line = readline(prompt);
    if (line == nullptr) {
      out_ << "\n";  // Ctrl-D leaves the cursor after the prompt
      return make_error(ErrorCode::kCancelled, "end of input");
    }
    std::string text(line);
    std::free(line);
    if (!trim(text).empty()) add_history(text.c_str());
    return text;
  }
  out_ << prompt;
  out_.flush();
  std::string text;
  int c;
  while ((c = std::fgetc(in_)) != EOF && c != '\n') text.push_back(static_cast<char>(c));
  if (c == EOF && text.empty()) {
    // End the prompt's line, so that what is printed next starts a line.
    out_ << "\n";
    return make_error(ErrorCode::kCancelled, "end of input");
  }
  out_ << text << "\n";
  return text;
}

std::string describe_status(const Question& question, const World& world) {
  const Universe& u = *world.universe;
  const Vocabulary& v = world.vocabulary;
  std::string out = "World (" + world.location + "):\n";
  for (ObjectId p : u.of_kind(ObjectKind::kReceptacle)) {
    if (!world.state.holds(Fact(v.openable, {p}))) continue;
    out += "  " + u.name(p) + " is " + (world.state.holds(Fact(v.closed, {p})) ? "closed" : "open") + "\n";
  }
  for (ObjectId place = 0; place < u.size(); ++place) {
    if (u.info(place).kind == ObjectKind::kItem) continue;
    std::string items;
    for (const Fact& f : world.state.facts())
      if ((f.predicate == v.on || f.predicate == v.in) && f.args[1] == place) items += " " + u.name(f.args[0]);
    if (!items.empty()) out += "  " + std::string(u.info(place).kind == ObjectKind::kSurface ? "on " : "in ") + u.name(place) + ":" + items + "\n";
  }
  for (const Fact& f : world.state.facts())
    if (f.predicate == v.holding) out += "  holding " + u.name(f.args[0]) + "\n";
  out += "Progress:";
  if (!question.task.empty()) out += " task " + question.task;
  if (!question.subtask.empty()) out += ", subtask " + question.subtask;
  if (question.object) out += ", working on " + u.name(*question.object);
  out += "\n";
  return out;
}

void TerminalInstructor::print_status(const Question& question, const World& world) {
  out_ << describe_status(question, world);
}

Result<std::string> TerminalInstructor::answer(const Question& question, const World& world) {
  out_ << "Agent: " << question.text << "\n";
  for (;;) {
    auto line = read_line("Instructor: ");
    if (!line) return line;
    std::string text = to_lower(trim(*line));
    if (text == "status") {
      print_status(question, world);
      continue;
    }
    if (text == "help") {
      out_ << "Answer the agent in English (see docs/language.md), or type 'status' to see the world, "
              "or press Ctrl-D to stop; what was learned is kept.\n";
      continue;
    }
    if (text.empty()) continue;
    return std::string(trim(*line));
  }
}

void TerminalInstructor::hear(std::string_view statement) { out_ << "Agent: " << statement << "\n"; }

}  // namespace apprentice
