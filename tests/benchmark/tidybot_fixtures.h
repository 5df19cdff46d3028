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

}  // namespace apprentice::benchmark::testing
