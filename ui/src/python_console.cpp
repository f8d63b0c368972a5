// The window's Python console: Python embedded on the solver's thread, the module `tessera`
// built in from the same bindings as the extension module, and Python's own interactive
// interpreter (code.InteractiveInterpreter) deciding what a line means.
#include "python_console.hpp"

#include <pybind11/embed.h>

#include "bindings.hpp"
#include "tessera/script/script.hpp"

namespace py = pybind11;

PYBIND11_EMBEDDED_MODULE(tessera, mod) {
  tessera::python::define_module(mod);
}

namespace tessera::ui {

namespace {

// The prompt's interpreter: remembers the last exception's one-line text, and says whether the
// lines so far are a statement still open.
constexpr const char* kConsoleClass = R"(
import code as _code, sys as _sys
class TesseraConsole(_code.InteractiveInterpreter):
    error = ""
    def _remember(self):
        t, v = _sys.exc_info()[:2]
        self.error = f"{t.__name__}: {v}" if str(v) else t.__name__
    def showtraceback(self):
        self._remember()
        super().showtraceback()
    def showsyntaxerror(self, filename=None, **kw):
        self._remember()
        super().showsyntaxerror(filename)
    def incomplete(self, source):
        try:
            return self.compile(source, "<console>", "single") is None
        except (OverflowError, SyntaxError, ValueError):
            return False
class Stream:
    encoding = "utf-8"
    def __init__(self, write):
        self._write = write
    def write(self, text):
        self._write(text)
        return len(text)
    def flush(self):
        pass
    def isatty(self):
        return False
)";

}  // namespace

struct PythonConsole::Impl {
  Output out;
  const std::atomic<bool>* stop = nullptr;
  std::string pending[2];  // output not yet ended by a newline: stdout, stderr
  py::object console, ns, model_obj;
  python::PyModel* model = nullptr;
  // m.on_cycle's callbacks before the last statement (put back when it fails).
  std::vector<python::PyModel::Callback> callbacks_before;
  // Python outlives the console (it is never finalised: the window may close on another
  // thread), so the references are left to it.
  ~Impl() {
    console.release(), ns.release(), model_obj.release();
    for (auto& c : callbacks_before) c.fn.release();
  }
  void write(const std::string& text, int stream) {
    std::string& p = pending[stream];
    p += text;
    for (size_t nl; (nl = p.find('\n')) != std::string::npos; p.erase(0, nl + 1))
      out(p.substr(0, nl), stream == 1);
  }
  void flush() {
    for (int s = 0; s < 2; ++s)
      if (!pending[s].empty()) out(pending[s], s == 1), pending[s].clear();
  }
};

bool python_console_available() {
  return true;
}

PythonConsole::PythonConsole(Output out, const std::atomic<bool>* stop)
    : impl_(std::make_unique<Impl>()) {
  impl_->out = std::move(out), impl_->stop = stop;
  // Started once per process, its lock released: each call takes it (a second window's worker
  // is another thread).
  if (!Py_IsInitialized()) {
    py::initialize_interpreter(false);
    PyEval_SaveThread();
  }
  py::gil_scoped_acquire gil;
  py::dict helpers;
  py::exec(kConsoleClass, helpers);
  Impl* self = impl_.get();
  py::module_ sys = py::module_::import("sys");
  for (int s = 0; s < 2; ++s)
    sys.attr(s == 0 ? "stdout" : "stderr") = helpers["Stream"](
        py::cpp_function([self, s](const std::string& text) { self->write(text, s); }));
  // Nothing to read from: input() meets the end of its input.
  sys.attr("stdin") = py::module_::import("io").attr("StringIO")("");
  impl_->ns = py::dict();
  impl_->ns["__name__"] = "__console__";
  impl_->ns["tessera"] = py::module_::import("tessera");
  try {
    impl_->ns["np"] = py::module_::import("numpy");
  } catch (const py::error_already_set&) {
    // numpy missing: the arrays say so when first read.
  }
  impl_->console = helpers["TesseraConsole"](impl_->ns);
}

PythonConsole::~PythonConsole() = default;

void PythonConsole::bind(Interpreter& interp) {
  py::gil_scoped_acquire gil;
  Impl& s = *impl_;
  if (!s.model) {
    s.model = new python::PyModel(interp);
    s.model_obj = py::cast(s.model, py::return_value_policy::take_ownership);
    s.ns["m"] = s.model_obj;
  }
  s.model->interp = &interp;
  s.model->callbacks.clear(), s.model->pending.reset();
  s.model->stop = s.stop;
}

bool PythonConsole::incomplete(const std::string& source) {
  py::gil_scoped_acquire gil;
  try {
    return impl_->console.attr("incomplete")(source).cast<bool>();
  } catch (const py::error_already_set&) {
    return false;  // complete: running it reports the error (a RecursionError, say)
  }
}

std::string PythonConsole::run(const std::string& source) {
  py::gil_scoped_acquire gil;
  Impl& s = *impl_;
  if (s.model) s.callbacks_before = s.model->callbacks;
  s.console.attr("error") = "";
  std::string error;
  try {
    s.console.attr("runsource")(source, "<console>", "single");
    error = s.console.attr("error").cast<std::string>();
  } catch (py::error_already_set& e) {
    // What the prompt lets through: SystemExit.
    error = e.matches(PyExc_SystemExit) ? "SystemExit: close the window to leave" : e.what();
    s.write(error + "\n", 1);
  }
  s.flush();
  return error;
}

void PythonConsole::observe(const Model& m) {
  if (!impl_->model || impl_->model->callbacks.empty()) return;
  py::gil_scoped_acquire gil;
  impl_->model->observe(m);
}

void PythonConsole::rollback() {
  py::gil_scoped_acquire gil;
  if (impl_->model) impl_->model->callbacks = impl_->callbacks_before;
}

}  // namespace tessera::ui
