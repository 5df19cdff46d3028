// The fleet-prior curve (docs/benchmarks.md, "The fleet-prior curve";
// experiment/fleet_curve.h): HOUSEHOLDS households taught one after another
// into the store at STORE (started over), each household's intent the
// scenario's with each kind's place changed with probability VARY, and
// what each household's teacher said: instructions, words, yes/no.
//
//   bench_fleet SCENARIO STORE [HOUSEHOLDS [VARY [SEED]]] [--no-prior] [--condition C]
//
// STORE is an SQLite path or a postgresql:// URL, as --knowledge takes.
// --no-prior: the agent leaves the other households' goals out (the
// policy rules are still shared), for the curve without the prior.
//
//   bench_fleet learn SCENARIO STORE HOUSEHOLD [--condition C]
//
// One learner of the fleet's kill test (scripts/fleet-kill-test.sh): the
// simulated instructor teaches SCENARIO's task into HOUSEHOLD of STORE,
// which is not started over. Logs at debug level on stderr, among them
// "goal saved: ..." once each goal is durable. Exit 0 when taught, 3 when
// the store failed (unreachable, in use), 1 otherwise.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "experiment/fleet_curve.h"
#include "face/apprentice.h"
#include "instructor/simulated_instructor.h"
#include "util/log.h"

namespace {

int learn(const std::vector<std::string>& args, const std::string& condition) {
  if (args.size() != 3) {
    std::fprintf(stderr, "usage: bench_fleet learn SCENARIO STORE HOUSEHOLD [--condition C]\n");
    return 2;
  }
  apprentice::configure_logging(apprentice::LogLevel::kDebug);
  auto scenario = apprentice::load_world(args[0]);
  if (!scenario) {
    std::fprintf(stderr, "bench_fleet: %s\n", scenario.error().describe().c_str());
    return 2;
  }
  apprentice::AgentSpec spec = apprentice::default_agent_spec();
  spec.condition = condition;
  spec.knowledge = args[1];
  spec.household = args[2];
  auto store_failed = [](const apprentice::Error& e) {
    std::fprintf(stderr, "bench_fleet: %s\n", e.describe().c_str());
    return e.code == apprentice::ErrorCode::kIo || e.code == apprentice::ErrorCode::kUnavailable ? 3 : 1;
  };
  auto session = apprentice::make_agent_session(spec, *scenario);
  if (!session) return store_failed(session.error());
  apprentice::SimulatedInstructor instructor(*scenario);
  auto report = (*session)->learn(instructor);
  if (!report) return store_failed(report.error());
  if (report->stopped) {
    std::fprintf(stderr, "bench_fleet: stopped: %s\n", report->stop_reason.c_str());
    return 3;
  }
  std::printf("%s: %d of %d goal assertions hold\n", args[0].c_str(), report->assertions_achieved,
              report->assertions_total);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> positional;
  apprentice::FleetCurveOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--no-prior") options.fleet_prior = false;
    else if (arg == "--condition" && i + 1 < argc) options.condition = argv[++i];
    else positional.push_back(arg);
  }
  if (!positional.empty() && positional[0] == "learn")
    return learn(std::vector<std::string>(positional.begin() + 1, positional.end()), options.condition);
  if (positional.size() < 2 || positional.size() > 5) {
    std::fprintf(stderr, "usage: bench_fleet SCENARIO STORE [HOUSEHOLDS [VARY [SEED]]] [--no-prior] [--condition C]\n");
    return 2;
  }
  options.knowledge = positional[1];
  try {
    if (positional.size() > 2) options.households = std::stoi(positional[2]);
    if (positional.size() > 3) options.vary = std::stod(positional[3]);
    if (positional.size() > 4) options.seed = static_cast<unsigned>(std::stoul(positional[4]));
  } catch (const std::exception&) {
    std::fprintf(stderr, "bench_fleet: HOUSEHOLDS and SEED are whole numbers, VARY a number from 0 to 1\n");
    return 2;
  }
  auto scenario = apprentice::load_world(positional[0]);
  if (!scenario) {
    std::fprintf(stderr, "bench_fleet: %s\n", scenario.error().describe().c_str());
    return 2;
  }
  auto curve = apprentice::run_fleet_curve(*scenario, options);
  if (!curve) {
    std::fprintf(stderr, "bench_fleet: %s\n", curve.error().describe().c_str());
    return 1;
  }
  std::printf("%s, %d households, vary %.2f, seed %u, %s, fleet prior %s\n\n", positional[0].c_str(),
              options.households, options.vary, options.seed, options.condition.c_str(),
              options.fleet_prior ? "on" : "off");
  std::fputs(apprentice::format_fleet_curve(*curve).c_str(), stdout);
  return 0;
}
