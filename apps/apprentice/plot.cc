#include "plot.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>

#include <cstdlib>
#include <fstream>
#include <vector>

extern char** environ;

namespace apprentice::cli {

namespace {

// The exit status apprentice.plot uses when matplotlib cannot be imported.
constexpr int kPlotMissingMatplotlib = 3;

const char* const kInstallHint =
    "install Debian's packages with: sudo apt-get install python3 python3-matplotlib pybind11-dev python3-dev "
    "(or bash scripts/install-deps.sh), then rebuild with make";

// The directory holding the apprentice package, built or installed next to
// this program; empty if there is none.
std::filesystem::path module_dir() {
  std::error_code ec;
  std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  std::filesystem::path bin = exe.parent_path();
  for (const std::filesystem::path& dir : {bin / "python", bin.parent_path() / "lib" / "python3" / "dist-packages"}) {
    if (!std::filesystem::exists(dir / "apprentice" / "plot.py", ec)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(dir / "apprentice", ec))
      if (entry.path().filename().string().rfind("_apprentice", 0) == 0 && entry.path().extension() == ".so")
        return dir;
  }
  return {};
}

std::string python_program() {
  const char* chosen = std::getenv("APPRENTICE_PYTHON");
  return chosen && *chosen ? chosen : "/usr/bin/python3";
}

// The environment with `dir` put in front of PYTHONPATH.
std::vector<std::string> environment_with_pythonpath(const std::filesystem::path& dir) {
  std::vector<std::string> env;
  std::string path = "PYTHONPATH=" + dir.string();
  for (char** e = environ; *e; ++e) {
    std::string entry = *e;
    if (entry.rfind("PYTHONPATH=", 0) == 0) {
      if (entry.size() > 11) path += ":" + entry.substr(11);
      continue;
    }
    env.push_back(entry);
  }
  env.push_back(path);
  return env;
}

// Runs the program; its exit status, or -1 when it could not be started
// (127 from posix_spawn's child when the program does not exist).
int run(const std::vector<std::string>& args, const std::vector<std::string>& env) {
  std::vector<char*> argv, envp;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  for (const std::string& e : env) envp.push_back(const_cast<char*>(e.c_str()));
  envp.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), envp.data()) != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

Status plot_results(const std::string& results_json, const std::filesystem::path& out, bool paper) {
  std::string extension = out.extension().string();
  if (extension != ".svg" && extension != ".png")
    return make_error(ErrorCode::kInvalidInput, "--plot " + out.string() + ": the figure must be an .svg or .png file");
  std::string python = python_program();
  if (access(python.c_str(), X_OK) != 0)
    return make_error(ErrorCode::kFailedPrecondition,
                      "--plot needs Python 3 (" + python + " is missing): " + kInstallHint);
  std::filesystem::path dir = module_dir();
  if (dir.empty())
    return make_error(ErrorCode::kFailedPrecondition,
                      "--plot needs the apprentice Python module, which was not built next to this program: " +
                          std::string(kInstallHint));
  char tmpl[] = "/tmp/apprentice-results-XXXXXX";
  int fd = mkstemp(tmpl);
  if (fd < 0) return make_error(ErrorCode::kIo, "cannot create a temporary file for the results");
  close(fd);
  std::filesystem::path json_path = tmpl;
  {
    std::ofstream file(json_path, std::ios::binary);
    file << results_json;
    if (!file) {
      std::filesystem::remove(json_path);
      return make_error(ErrorCode::kIo, json_path.string() + ": write failed");
    }
  }
  std::vector<std::string> args = {python, "-m", "apprentice.plot", json_path.string(), "-o", out.string()};
  if (!paper) args.push_back("--no-paper");
  int status = run(args, environment_with_pythonpath(dir));
  std::error_code ec;
  std::filesystem::remove(json_path, ec);
  if (status == 0) return {};
  if (status == kPlotMissingMatplotlib)
    return make_error(ErrorCode::kFailedPrecondition, "--plot needs matplotlib: " + std::string(kInstallHint));
  if (status < 0 || status == 127)
    return make_error(ErrorCode::kFailedPrecondition, "--plot could not run " + python + ": " + kInstallHint);
  return make_error(ErrorCode::kIo, "--plot: drawing " + out.string() + " failed (python3 -m apprentice.plot exited " +
                                        std::to_string(status) + ")");
}

}  // namespace apprentice::cli
