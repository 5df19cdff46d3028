// Where a knowledge store is, as a location string: an SQLite file's path
// or a PostgreSQL URL. Apart from knowledge/store.h so that the engines can
// name a store in messages without depending on the store that opens them.
#pragma once

#include <string>
#include <string_view>

#include "util/result.h"

namespace apprentice {

// Whether `location` names a PostgreSQL database (postgresql:// or
// postgres://) rather than an SQLite file.
bool is_postgres_location(std::string_view location);

// `location` as messages may show it: a PostgreSQL URL without the
// password (user:password@ becomes user@, a password=... parameter is
// dropped); a path as it is.
std::string scrub_store_location(std::string_view location);

// Whether `name` can name a household (--household): 1 to 64 letters,
// digits, '-', '_' or '.'. kInvalidInput, one sentence, otherwise.
Status check_household_name(std::string_view name);

// Whether `name` can name a robot (--robot), the name saved with each goal
// and rule it learns and said in the news ("Robot kitchen-2 just learned
// ..."): 1 to 64 letters, digits, spaces, '-', '_' or '.', not beginning or
// ending with a space. kInvalidInput, one sentence, otherwise.
Status check_robot_name(std::string_view name);

// The robot's name when none is given: the host name, cut to what
// check_robot_name accepts (its first label, 64 characters), or "robot".
std::string default_robot_name();

}  // namespace apprentice
