// Batch mode: runs a script headless, prints progress, writes results even after an error.
#include "batch.hpp"

#include <filesystem>
#include <iostream>

#include "tessera/parallel.hpp"
#include "tessera/script.hpp"
#include "tessera/ui/figure_writer.hpp"

namespace fs = std::filesystem;

namespace tessera::app {

int run_batch(const std::string& script, std::string out_dir, int threads, bool quiet) {
  if (out_dir.empty()) {
    const fs::path p(script);
    out_dir = (p.parent_path() / (p.stem().string() + "_out")).string();
  }
  set_thread_count(threads);
  Interpreter interp(out_dir, [quiet](const std::string& s) {
    if (!quiet || s.find("warning") != std::string::npos) std::cout << s << std::endl;
  });
  // Figures are drawn with QPainter, so a headless machine writes them too.
  interp.set_figure_sink(ui::figure_sink());
  int status = 0;
  try {
    interp.run_file(script);
  } catch (const ScriptError& e) {
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

}  // namespace tessera::app
