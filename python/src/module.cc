// The extension module apprentice._apprentice; the package apprentice
// (python/apprentice/__init__.py) re-exports it.
#include <cstdlib>

#include "bindings.h"
#include "util/log.h"

#ifndef APPRENTICE_DATA_DIR
#define APPRENTICE_DATA_DIR "data"
#endif
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

std::filesystem::path data_dir() {
  if (const char* chosen = std::getenv("APPRENTICE_DATA"); chosen && *chosen) return chosen;
  std::error_code ec;
  std::filesystem::path built = APPRENTICE_DATA_DIR;
  if (std::filesystem::exists(built / "prompts" / "goal.txt", ec)) return built;
  // Installed: <prefix>/lib/python3/dist-packages/apprentice/ -> <prefix>/share/apprentice.
  py::object file = py::module_::import("apprentice._apprentice").attr("__file__");
  std::filesystem::path here = std::filesystem::path(file.cast<std::string>()).parent_path();
  for (std::filesystem::path dir = here; !dir.empty() && dir != dir.root_path(); dir = dir.parent_path())
    if (std::filesystem::exists(dir / "share" / "apprentice" / "prompts" / "goal.txt", ec))
      return dir / "share" / "apprentice";
  return built;
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
}
