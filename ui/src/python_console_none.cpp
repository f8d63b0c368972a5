// The console of a build without Python: it says how to get it.
#include <stdexcept>

#include "python_console.hpp"

namespace tessera::ui {

struct PythonConsole::Impl {};

bool python_console_available() {
  return false;
}

PythonConsole::PythonConsole(Output, const std::atomic<bool>*) {
  throw std::runtime_error(
      "this build has no Python: install python3-dev, pybind11-dev and python3-numpy "
      "(scripts/install-deps.sh) and build again");
}

PythonConsole::~PythonConsole() = default;
void PythonConsole::bind(Interpreter&) {}
bool PythonConsole::incomplete(const std::string&) {
  return false;
}
std::string PythonConsole::run(const std::string&) {
  return {};
}
void PythonConsole::observe(const Model&) {}
void PythonConsole::rollback() {}

}  // namespace tessera::ui
