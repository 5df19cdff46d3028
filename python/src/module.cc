// The extension module apprentice._apprentice; the package apprentice
// (python/apprentice/__init__.py) re-exports it.
#include <chrono>
#include <cstdlib>
#include <limits>

#include "bindings.h"
#include "util/log.h"

#ifndef APPRENTICE_VERSION
#define APPRENTICE_VERSION "0"
#endif

namespace apprentice::python {

namespace {

// Owned by the module, which is never unloaded.
PyObject* error_class = nullptr;

}  // namespace

void raise_error(const Error& error) {
  py::object exception = py::reinterpret_borrow<py::object>(error_class)(error.describe());
  exception.attr("code") = std::string(to_string(error.code));
  exception.attr("message") = error.message;
  PyErr_SetObject(error_class, exception.ptr());
  throw py::error_already_set();
}

long whole_number(const py::handle& value, const char* name, long low, long high) {
  if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value))
    raise_error(Error{ErrorCode::kInvalidInput, std::string(name) + ": " + std::string(py::repr(value)) + " is not a whole number"});
  long number = value.cast<long>();
  if (number < low || number > high)
    raise_error(Error{ErrorCode::kInvalidInput, std::string(name) + ": " + std::to_string(number) + " is out of range (" +
                                                    std::to_string(low) + " to " + std::to_string(high) + ")"});
  return number;
}

bool flag(const py::handle& value, const char* name) {
  if (!py::isinstance<py::bool_>(value))
    raise_error(Error{ErrorCode::kInvalidInput, std::string(name) + ": " + std::string(py::repr(value)) + " is not True or False"});
  return value.cast<bool>();
}

std::string text(const py::handle& value, const char* name) {
  if (!py::isinstance<py::str>(value))
    raise_error(Error{ErrorCode::kInvalidInput, std::string(name) + ": " + std::string(py::repr(value)) + " is not a str"});
  return value.cast<std::string>();
}

void apply_agent_options(const py::kwargs& options, AgentSpec& spec) {
  constexpr long kMost = std::numeric_limits<int>::max();
  for (const auto& [key, value] : options) {
    const std::string name = key.cast<std::string>();
    if (value.is_none()) continue;  // the default
    if (name == "use_rules") spec.use_rules = flag(value, "use_rules");
    else if (name == "max_reprompts") spec.max_reprompts = whole_number(value, "max_reprompts", 0, 16);
    else if (name == "goal_repair") spec.goal_repair = text(value, "goal_repair");
    else if (name == "offer_ungrounded") spec.offer_ungrounded = flag(value, "offer_ungrounded");
    else if (name == "llm_model") spec.llm.model = text(value, "llm_model");
    else if (name == "llm_api_key") spec.llm.api_key = text(value, "llm_api_key");
    else if (name == "llm_timeout_ms") spec.llm.timeout = std::chrono::milliseconds(whole_number(value, "llm_timeout_ms", 1, kMost));
    else if (name == "llm_connect_timeout_ms")
      spec.llm.connect_timeout = std::chrono::milliseconds(whole_number(value, "llm_connect_timeout_ms", 1, kMost));
    else if (name == "llm_seed") spec.llm.seed = static_cast<int>(whole_number(value, "llm_seed", 0, kMost));
    else if (name == "llm_optional") spec.llm.optional = flag(value, "llm_optional");
    else if (name == "llm_goal_responses") spec.llm.goal_responses = whole_number(value, "llm_goal_responses", 1, 10);
    else if (name == "household") spec.household = text(value, "household");
    else if (name == "robot") spec.robot = text(value, "robot");
    else
      raise_error(Error{ErrorCode::kInvalidInput,
                        "unknown option " + name + " (options: use_rules, max_reprompts, goal_repair, offer_ungrounded, "
                        "llm_model, llm_api_key, llm_timeout_ms, llm_connect_timeout_ms, llm_seed, llm_optional, "
                        "llm_goal_responses, household, robot)"});
  }
}

void bind_errors(py::module_& m) {
  error_class = PyErr_NewExceptionWithDoc(
      "apprentice.Error",
      "An error from apprentice. `code` says what kind: 'invalid input', 'not found', 'failed precondition', "
      "'unavailable', 'deadline exceeded', 'i/o error', 'data loss' or 'cancelled'; `message` says what happened.",
      PyExc_Exception, nullptr);
  if (error_class == nullptr) throw py::error_already_set();
  m.add_object("Error", py::handle(error_class));
}

}  // namespace apprentice::python

PYBIND11_MODULE(_apprentice, m) {
  using namespace apprentice::python;
  m.doc() = "apprentice's C++ core; import the package apprentice instead.";
  m.attr("__version__") = APPRENTICE_VERSION;
  // Library code logs warnings to stderr, as the CLI does (spdlog's own
  // default would print its info lines on stdout).
  try {
    apprentice::configure_logging(apprentice::LogLevel::kWarn);
  } catch (const std::exception&) {
    // Already configured by the program that embeds Python.
  }
  bind_errors(m);
  bind_scenario(m);
  bind_knowledge(m);
  bind_agent(m);
  bind_experiment(m);
  bind_plan_and_interpret(m);
}
