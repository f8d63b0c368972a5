// The tessera executable. Batch mode runs a model script headless; the desktop window is built
// by the GUI issue and is not part of this program yet.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>

#include "tessera/parallel.hpp"
#include "tessera/script.hpp"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  CLI::App app{"Tessera: distinct element models of blocky rock and masonry"};
  std::string script, out_dir;
  int threads = 1;
  bool quiet = false;
  app.add_option("--batch", script, "Run a model script headless")->check(CLI::ExistingFile);
  app.add_option("--out", out_dir, "Output folder (default: <script>_out beside the script)");
  app.add_option("--threads", threads, "Worker threads (results are identical at any count)")
      ->check(CLI::Range(1, 256));
  app.add_flag("--quiet", quiet, "Print errors and warnings only");
  CLI11_PARSE(app, argc, argv);
  if (script.empty()) {
    std::cerr << "tessera: the desktop window is not available in this build; run a model with "
                 "'tessera --batch FILE'\n";
    return 2;
  }
  if (out_dir.empty()) {
    const fs::path p(script);
    out_dir = (p.parent_path() / (p.stem().string() + "_out")).string();
  }
  tessera::set_thread_count(threads);
  tessera::Interpreter interp(out_dir, [quiet](const std::string& s) {
    if (!quiet || s.find("warning") != std::string::npos) std::cout << s << std::endl;
  });
  int status = 0;
  try {
    interp.run_file(script);
  } catch (const tessera::ScriptError& e) {
    std::cerr << e.what() << std::endl;
    status = 1;
  }
  // Results so far are written even after an error, so nothing computed is lost.
  try {
    interp.finish();
  } catch (const std::exception& e) {
    std::cerr << "tessera: " << e.what() << std::endl;
    return 1;
  }
  if (!quiet) std::cout << "results in " << out_dir << std::endl;
  return status;
}
