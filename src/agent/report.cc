#include "agent/report.h"

namespace apprentice {

std::string_view to_string(GoalSource source) {
  switch (source) {
    case GoalSource::kNone: return "";
    case GoalSource::kMemory: return "memory";
    case GoalSource::kInstructor: return "instructor";
    case GoalSource::kLlm: return "llm";
    case GoalSource::kAnalogy: return "analogy";
    case GoalSource::kLikeness: return "likeness";
    case GoalSource::kRule: return "rule";
    case GoalSource::kPersonRule: return "person's rule";
    case GoalSource::kFleet: return "fleet";
    case GoalSource::kDecision: return "decision";
  }
  return "";
}

}  // namespace apprentice
