// Headless runs of Python files: python3 with the tessera module importable.
#pragma once

#include <string>

namespace tessera::app {

// Runs a Python file with results in out_dir; returns the interpreter's exit status (or 128 +
// the signal that ended it).
int run_python_batch(const std::string& script, const std::string& out_dir, int threads,
                     bool quiet);

}  // namespace tessera::app
