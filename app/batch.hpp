// Headless runs: a model script from start to end, results and figures in an output folder.
#pragma once

#include <string>

namespace tessera::app {

// Runs the script; returns the exit status (0 done, 1 an error in the script or the run).
int run_batch(const std::string& script, std::string out_dir, int threads, bool quiet);

}  // namespace tessera::app
