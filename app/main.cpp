// The tessera executable: `tessera [FILE]` opens the desktop window (with a model script);
// `tessera --batch FILE` runs a script (or a Python file using the tessera module) headless.
#include <CLI/CLI.hpp>
#include <QApplication>
#include <QGuiApplication>
#include <cstdio>
#include <cstdlib>

#include "batch.hpp"
#include "tessera/core/parallel.hpp"
#include "tessera/ui/main_window.hpp"
#include "tessera/ui/vtk_view.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Tessera: distinct element models of blocky rock and masonry"};
  std::string script, batch, out_dir;
  int threads = 1;
  bool quiet = false;
  app.add_option("file", script, "Model script to open in the window")->check(CLI::ExistingFile);
  app.add_option("--batch", batch, "Run a model script (.tess) or a Python file (.py) headless")
      ->check(CLI::ExistingFile);
  app.add_option("--out", out_dir, "Output folder (default: <script>_out beside the script)");
  app.add_option("--threads", threads, "Worker threads (results are identical at any count)")
      ->check(CLI::Range(1, 256));
  app.add_flag("--quiet", quiet, "Print errors and warnings only");
  CLI11_PARSE(app, argc, argv);
  QCoreApplication::setOrganizationName("Tessera");
  QCoreApplication::setApplicationName("Tessera");
  if (!batch.empty()) {
    // Headless: fonts for figures without a display.
    if (!std::getenv("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    // Qt's notes about the desktop session mean nothing to a batch run.
    qInstallMessageHandler([](QtMsgType type, const QMessageLogContext&, const QString& msg) {
      if (type >= QtCriticalMsg || !msg.startsWith("QStandardPaths:"))
        std::fprintf(stderr, "%s\n", qPrintable(msg));
    });
    QGuiApplication gui(argc, argv);
    return tessera::app::run_batch(batch, out_dir, threads, quiet);
  }
  if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY") &&
      !std::getenv("QT_QPA_PLATFORM")) {
    std::fprintf(stderr,
                 "tessera: no display to open the window on; run a model headless with "
                 "'tessera --batch FILE'\n");
    return 2;
  }
  tessera::ui::VtkView::setDefaultSurfaceFormat();
  QApplication gui(argc, argv);
  tessera::set_thread_count(threads);
  tessera::ui::MainWindow window;
  window.show();
  if (!script.empty()) window.openScript(QString::fromStdString(script));
  return QApplication::exec();
}
