// `experiment --plot FILE`: the results drawn as a figure by the Python
// module (python3 -m apprentice.plot, which uses matplotlib).
#pragma once

#include <filesystem>
#include <string>

#include "util/result.h"

namespace apprentice::cli {

// Draws `results_json` (as `experiment --json` prints it) into `out`, an
// .svg or .png file, with the paper's figures beside ours when `paper`.
// Runs $APPRENTICE_PYTHON, else Debian's /usr/bin/python3, with the module
// found next to this program (build/python, or lib/python3/dist-packages
// of the installation). Errors: kInvalidInput for another extension;
// kFailedPrecondition, saying what to install, when Python, the module or
// matplotlib is missing; kIo when the figure cannot be written.
Status plot_results(const std::string& results_json, const std::filesystem::path& out, bool paper);

}  // namespace apprentice::cli
