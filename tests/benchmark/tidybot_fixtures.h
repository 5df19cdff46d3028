// Small TidyBot scenarios written for these tests (not the benchmark's), in
// the benchmark's own format.
#pragma once

#include <string>

namespace apprentice::benchmark::testing {

// Two people: one sorts clothes from toys, one puts things on shelves by
// position. Written here; the benchmark's scenarios are in ../shared.
inline const std::string kTwoScenarios = R"(- annotator_notes: Put shirts in the hamper and blocks in the toy chest.
  benchmark_index: 7
  receptacles:
  - hamper
  - toy chest
  room: bedroom
  seen_objects:
  - polo shirt
  - wooden block
  seen_placements:
  - - polo shirt
    - hamper
  - - wooden block
    - toy chest
  tags:
  - category
  unseen_objects:
  - flannel shirt
  - foam block
  - polo shirt 2
  unseen_placements:
  - - flannel shirt
    - hamper
  - - foam block
    - toy chest
  - - polo shirt 2
    - hamper
- annotator_notes: Put mugs on the top shelf and plates on the bottom shelf.
  benchmark_index: 9
  receptacles:
  - top shelf
  - bottom shelf
  room: kitchen
  seen_objects:
  - Disney mug
  - dinner plate
  seen_placements:
  - - Disney mug
    - top shelf
  - - dinner plate
    - bottom shelf
  tags:
  - category
  - attribute
  unseen_objects:
  - coffee mug
  unseen_placements:
  - - coffee mug
    - top shelf
)";

// Answers to the two scenarios, in the keys of the TidyBot corpus
// (llm-dev.jsonl), written here: a summary of each one's seen placements,
// placements by it and by the person's note. The coffee mug is put on the
// wrong shelf, as a model may.
inline const std::string kTwoScenariosAnswers =
    R"({"scenario": 7, "method": "summarization", "step": "summary", "receptacles": ["hamper", "toy chest"], "examples": [["polo shirt", "hamper"], ["wooden block", "toy chest"]], "completion": "", "summary": "Put shirts in the hamper and blocks in the toy chest."})"
    "\n"
    R"({"scenario": 7, "method": "summarization", "step": "placement", "receptacles": ["hamper", "toy chest"], "summary": "Put shirts in the hamper and blocks in the toy chest.", "objects": ["flannel shirt", "foam block", "polo shirt 2"], "completion": "", "placements": [["flannel shirt", "hamper"], ["foam block", "toy chest"], ["polo shirt 2", "hamper"]]})"
    "\n"
    R"({"scenario": 7, "method": "human-summary", "step": "placement", "receptacles": ["hamper", "toy chest"], "summary": "Put shirts in the hamper and blocks in the toy chest.", "objects": ["polo shirt", "wooden block"], "completion": "", "placements": [["polo shirt", "hamper"], ["wooden block", "toy chest"]]})"
    "\n"
    R"({"scenario": 9, "method": "summarization", "step": "summary", "receptacles": ["top shelf", "bottom shelf"], "examples": [["Disney mug", "top shelf"], ["dinner plate", "bottom shelf"]], "completion": "", "summary": "Put mugs on the top shelf and plates on the bottom shelf."})"
    "\n"
    R"({"scenario": 9, "method": "summarization", "step": "placement", "receptacles": ["top shelf", "bottom shelf"], "summary": "Put mugs on the top shelf and plates on the bottom shelf.", "objects": ["coffee mug"], "completion": "", "placements": [["coffee mug", "bottom shelf"]]})"
    "\n"
    R"({"scenario": 9, "method": "human-summary", "step": "placement", "receptacles": ["top shelf", "bottom shelf"], "summary": "Put mugs on the top shelf and plates on the bottom shelf.", "objects": ["Disney mug", "dinner plate"], "completion": "", "placements": [["Disney mug", "top shelf"], ["dinner plate", "bottom shelf"]]})"
    "\n";

}  // namespace apprentice::benchmark::testing
