// Batch mode: runs a script headless, prints progress, writes results even after an error.
#include "batch.hpp"

#include <atomic>
#include <csignal>
#include <filesystem>
#include <iostream>

#include "python_batch.hpp"
#include "tessera/core/parallel.hpp"
#include "tessera/io/state_io.hpp"
#include "tessera/script/script.hpp"
#include "tessera/ui/figure_writer.hpp"

namespace fs = std::filesystem;

namespace tessera::app {

namespace {
// The first SIGINT or SIGTERM asks the run to stop at the next cycle boundary (it then writes
// its results and a state file); a second one ends the process at once.
std::atomic<bool> g_stop{false};
volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_signal(int sig) {
  if (g_signal != 0) {
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  g_signal = sig;
  g_stop.store(true);
}

void install_signal_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}
}  // namespace

int run_batch(const std::string& script, std::string out_dir, int threads, bool quiet) {
  if (out_dir.empty()) {
    const fs::path p(script);
    out_dir = (p.parent_path() / (p.stem().string() + "_out")).string();
  }
  if (fs::path(script).extension() == ".py")
    return run_python_batch(script, out_dir, threads, quiet);
  set_thread_count(threads);
  Interpreter interp(out_dir, [quiet](const std::string& s) {
    if (!quiet || s.find("warning") != std::string::npos) std::cout << s << std::endl;
  });
  // Figures are drawn with QPainter, so a headless machine writes them too.
  interp.set_figure_sink(ui::figure_sink());
  install_signal_handlers();
  interp.set_stop_flag(&g_stop);
  // The results of a failed run show the model before the failing command (a cut or a zoning
  // half done is no result), or as it stood when a failing step or solve stopped.
  interp.set_rollback(true, false);
  int status = 0;
  try {
    interp.run_file(script);
  } catch (const ScriptError& e) {
    std::cerr << e.what() << std::endl;
    interp.set_outcome("error", e.what());
    status = 1;
  }
  if (const int sig = g_signal; sig != 0)
    interp.set_outcome("interrupted", sig == SIGINT ? "SIGINT" : "SIGTERM");
  // Results so far are written even after an error, so nothing computed is lost.
  try {
    interp.finish();
  } catch (const std::exception& e) {
    std::cerr << "tessera: " << e.what() << std::endl;
    return 1;
  }
  if (const int sig = g_signal; sig != 0) {
    // Interrupted: the model as it stands, for 'restore', beside the results.
    const std::string state = (fs::path(out_dir) / "interrupted.state").string();
    try {
      save_state(interp.model(), state);
    } catch (const std::exception& e) {
      std::cerr << "tessera: " << e.what() << std::endl;
    }
    std::cerr << script << ": interrupted by " << (sig == SIGINT ? "SIGINT" : "SIGTERM")
              << " at cycle " << interp.model().cycle << "; results in " << out_dir
              << ", the model in " << state << " (continue with 'restore " << state << "')"
              << std::endl;
    return 128 + sig;
  }
  if (!quiet) std::cout << "results in " << out_dir << std::endl;
  return status;
}

}  // namespace tessera::app
