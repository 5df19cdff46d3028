#include "instructor/terminal_instructor.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <ostream>

#include <editline/readline.h>

#include "util/text.h"

namespace apprentice {

namespace {

// Set by the SIGINT handler. A signal handler can reach nothing else, so
// this flag is the one piece of global state here; it is only read by the
// instructor that installed the handler.
volatile std::sig_atomic_t g_interrupted = 0;

extern "C" void on_interrupt(int) { g_interrupted = 1; }

}  // namespace

TerminalInstructor::TerminalInstructor(std::FILE* in, std::ostream& out, TerminalOptions options)
    : in_(in), out_(out), options_(options), interactive_(isatty(fileno(in)) != 0) {
  if (interactive_) {
    rl_instream = in_;
    using_history();
  }
  if (options_.catch_interrupt) {
    g_interrupted = 0;
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = 0;  // no SA_RESTART: a blocked read returns, so the reply loop sees the flag
    sigaction(SIGINT, &action, &previous_interrupt_handler_);
  }
}

TerminalInstructor::~TerminalInstructor() {
  if (options_.catch_interrupt) sigaction(SIGINT, &previous_interrupt_handler_, nullptr);
}

bool TerminalInstructor::interrupted() const { return options_.catch_interrupt && g_interrupted != 0; }

Result<std::string> TerminalInstructor::read_line(const char* prompt) {
  auto stop = [this](const char* why) {
    // End the prompt's line, so that what is printed next starts a line.
    out_ << "\n";
    out_.flush();
    return make_error(ErrorCode::kCancelled, why);
  };
  if (interrupted()) return stop("interrupted");
  if (interactive_) {
    out_.flush();
    char* line = readline(prompt);
    if (interrupted()) {
      std::free(line);
      return stop("interrupted");
    }
    if (line == nullptr) return stop("end of input");
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
  if (interrupted()) return stop("interrupted");
  if (c == EOF && text.empty()) return stop("end of input");
  out_ << text << "\n";
  return text;
}

Result<std::string> TerminalInstructor::answer(const Question& question, const World& world) {
  (void)world;
  out_ << "Agent: " << question.text << "\n";
  for (;;) {
    auto line = read_line("Instructor: ");
    if (!line) return line;
    if (trim(*line).empty()) continue;
    return std::string(trim(*line));
  }
}

void TerminalInstructor::hear(std::string_view statement) { out_ << "Agent: " << statement << "\n"; }

}  // namespace apprentice
