// The speed of reading a teacher's reply (issue 21): read_acts on every
// reply of the fresh corpora (tests/language/fresh/set1..set3), in the
// context each line describes, as the agent reads a reply at its question.
// The issue asks for at most 5 ms at the 95th percentile.
//
//   build/bench/bench_reply [ROUNDS]
//
// Round 1 reads every reply once with WordNet's answers not yet kept (the
// first replies of a process); each later round reads them all again, as a
// session reads its replies after its first ones. It prints the median, the
// 95th percentile and the slowest reply of the first round and of the later
// rounds, in wall time and in the thread's CPU time (on a loaded machine
// the wall time includes waiting for a core), and the slowest replies. Exit 0; 1 when a corpus cannot be read.
// Figures are of this build on this machine's load: docs/language.md.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "fresh_corpus.h"
#include "language/lexicon.h"

namespace {

using namespace apprentice;
using namespace apprentice::language;

struct Timed {
  double ms = 0;      // wall
  double cpu_ms = 0;  // this thread's CPU time: what the wall time is without waiting for a core
  std::string reply;
};

double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1000.0 + static_cast<double>(t.tv_nsec) / 1e6;
}

void print(const char* what, std::vector<Timed> times) {
  if (times.empty()) return;
  std::sort(times.begin(), times.end(), [](const Timed& a, const Timed& b) { return a.ms < b.ms; });
  std::printf("%s: %zu replies, wall: median %.3f ms, 95th percentile %.3f ms, slowest %.3f ms (\"%s\")\n", what,
              times.size(), times[times.size() / 2].ms, times[times.size() * 95 / 100].ms, times.back().ms,
              times.back().reply.c_str());
  std::sort(times.begin(), times.end(), [](const Timed& a, const Timed& b) { return a.cpu_ms < b.cpu_ms; });
  std::printf("%s: CPU: median %.3f ms, 95th percentile %.3f ms, slowest %.3f ms\n", what, times[times.size() / 2].cpu_ms,
              times[times.size() * 95 / 100].cpu_ms, times.back().cpu_ms);
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::max(2, std::atoi(argv[1])) : 5;
  spdlog::set_level(spdlog::level::warn);
  const Grounder grounder(Lexicon::open_default());
  struct Loaded {
    fresh::Corpus corpus;
    fresh::Worlds worlds;
  };
  std::vector<Loaded> sets;
  for (const char* set : {"set1", "set2", "set3"}) {
    std::filesystem::path folder = std::filesystem::path(APPRENTICE_SOURCE_DIR) / "tests/language/fresh" / set;
    Loaded loaded{fresh::read_corpus(folder), fresh::Worlds(folder)};
    if (!loaded.corpus.errors.empty() || loaded.corpus.lines.empty()) {
      std::fprintf(stderr, "bench_reply: cannot read the corpus in %s\n", folder.c_str());
      return 1;
    }
    sets.push_back(std::move(loaded));
  }
  std::vector<Timed> first, later;
  for (int round = 0; round < rounds; ++round)
    for (Loaded& set : sets)
      for (const fresh::Line& line : set.corpus.lines) {
        std::string error;
        const Scenario* scenario = set.worlds.get(line.world, error);
        if (scenario == nullptr) {
          std::fprintf(stderr, "bench_reply: %s\n", error.c_str());
          return 1;
        }
        ReplyContext context = fresh::context_of(line, scenario->world, error);
        const double cpu_start = thread_cpu_ms();
        auto start = std::chrono::steady_clock::now();
        ReplyActs acts = read_acts(grounder, scenario->world, context, line.reply);
        double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        const double cpu = thread_cpu_ms() - cpu_start;
        if (acts.acts.empty()) return 1;  // never: read_acts always has an act
        (round == 0 ? first : later).push_back({ms, cpu, line.reply});
      }
  print("first round", first);
  print("later rounds", later);
  // The slowest replies of the later rounds, each once.
  std::sort(later.begin(), later.end(), [](const Timed& a, const Timed& b) { return a.ms > b.ms; });
  std::vector<std::string> shown;
  for (const Timed& t : later) {
    if (shown.size() == 10) break;
    if (std::find(shown.begin(), shown.end(), t.reply) != shown.end()) continue;
    shown.push_back(t.reply);
    std::printf("  %.3f ms  \"%s\"\n", t.ms, t.reply.c_str());
  }
  return 0;
}
