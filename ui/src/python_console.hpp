// The window's Python console: an embedded interpreter on the solver's thread, with the module
// `tessera` built in and `m` the window's model (docs/python.md). Lines run as at Python's own
// prompt. Without Python in the build (python_console_none.cpp) the console says how to get it.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>

namespace tessera {
class Interpreter;
struct Model;
}  // namespace tessera

namespace tessera::ui {

// Whether this build embeds Python.
bool python_console_available();

class PythonConsole {
 public:
  // Printed output and tracebacks (error true), a line at a time.
  using Output = std::function<void(const std::string& text, bool error)>;
  // Starts Python (once a process) and readies a prompt; every call takes Python's lock and
  // leaves it free. Throws std::runtime_error if this build has no Python.
  PythonConsole(Output out, const std::atomic<bool>* stop);
  ~PythonConsole();
  PythonConsole(const PythonConsole&) = delete;
  PythonConsole& operator=(const PythonConsole&) = delete;
  // The interpreter `m` stands for from now on (a script opened makes a new one); callbacks set
  // with m.on_cycle for the one before are dropped.
  void bind(Interpreter& interp);
  // Whether the lines typed so far are a statement still open (a block, a bracket), as Python's
  // prompt decides; a syntax error is complete (running it reports it).
  bool incomplete(const std::string& source);
  // Runs a statement; on an exception writes the traceback and returns its last line, else "".
  std::string run(const std::string& source);
  // After each cycle of a run: the m.on_cycle callbacks that are due (throws if one raised).
  void observe(const Model& m);
  // The statement last run failed and its model was put back: its callbacks go too.
  void rollback();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tessera::ui
