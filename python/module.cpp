// The Python module `tessera`: a model driven by script commands, its cycle, callbacks every N
// cycles, named writes, and errors as Python exceptions with the interpreter's file:line text.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>

#include "bindings.hpp"
#include "tessera/core/parallel.hpp"
#include "tessera/core/step.hpp"

namespace tessera::python {

namespace {

// Where Python called from: the file and line of the innermost Python frame.
std::pair<std::string, int> caller() {
  PyFrameObject* f = PyEval_GetFrame();
  if (!f) return {"<python>", 1};
  const int line = PyFrame_GetLineNumber(f);
  const auto code =
      py::reinterpret_steal<py::object>(reinterpret_cast<PyObject*>(PyFrame_GetCode(f)));
  return {code.attr("co_filename").cast<std::string>(), line};
}

// The results folder: TESSERA_OUT (set by `tessera --batch`), else beside the running script
// as a script's would be (study.py: study_out/), else tessera_out.
std::string default_out() {
  if (const char* env = std::getenv("TESSERA_OUT"); env && *env) return env;
  const py::list argv = py::module_::import("sys").attr("argv");
  if (!argv.empty()) {
    const std::filesystem::path p(argv[0].cast<std::string>());
    if (p.has_stem() && p.extension() == ".py")
      return (p.parent_path() / (p.stem().string() + "_out")).string();
  }
  return "tessera_out";
}

// A number written so that the interpreter reads back the same double.
std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// Keyword arguments as key=value words of a command.
std::string keywords(const py::kwargs& kw) {
  std::string out;
  for (const auto& [k, v] : kw) {
    const std::string key = py::str(k);
    if (py::isinstance<py::str>(v))
      out += " " + key + "=" + v.cast<std::string>();
    else if (py::isinstance<py::float_>(v) || py::isinstance<py::int_>(v))
      out += " " + key + "=" + number(v.cast<double>());
    else
      throw py::type_error("keyword '" + key + "' takes a number or a string, not " +
                           std::string(py::str(py::type::of(v))));
  }
  return out;
}

// Rows of a (n, k) float array, or of one (k,) row repeated n times; ValueError otherwise.
std::vector<double> rows_of(const py::array_t<double, py::array::c_style | py::array::forcecast>& a,
                            size_t n, size_t k, const std::string& what) {
  std::vector<double> out(n * k);
  if (a.ndim() == 1 && static_cast<size_t>(a.shape(0)) == k) {
    for (size_t i = 0; i < n; ++i) std::copy(a.data(), a.data() + k, out.begin() + long(i * k));
  } else if (a.ndim() == 2 && static_cast<size_t>(a.shape(0)) == n &&
             static_cast<size_t>(a.shape(1)) == k) {
    std::copy(a.data(), a.data() + n * k, out.begin());
  } else {
    std::ostringstream msg;
    msg << what << " takes an array shaped (" << n << ", " << k << ") or (" << k << ",), not (";
    for (py::ssize_t d = 0; d < a.ndim(); ++d) msg << (d ? ", " : "") << a.shape(d);
    msg << (a.ndim() == 1 ? ",)" : ")");
    throw py::value_error(msg.str());
  }
  for (double v : out)
    if (!std::isfinite(v)) throw py::value_error(what + ": values must be finite");
  return out;
}

// Per-block turning quantities (a moment, an angular velocity): in 2D one number a block, given
// as a number for all or (n,); in 3D a vector, (n, 3) or (3,) for all. Empty if not given.
std::vector<double> turn_rows(
    const std::optional<py::array_t<double, py::array::c_style | py::array::forcecast>>& a,
    size_t n, size_t dm, const char* what) {
  if (!a) return {};
  if (dm == 1 && a->ndim() == 0) return std::vector<double>(n, *a->data());
  if (dm == 1 && a->ndim() == 1 && static_cast<size_t>(a->shape(0)) == n)
    return std::vector<double>(a->data(), a->data() + n);
  return rows_of(*a, n, dm, what);
}

// Whether row i of a write given for all blocks (no `blocks=`) is skipped: a joined 3D body
// takes its first piece's row (as m.blocks.load shows it), its other pieces' rows unused.
bool later_piece_row(const Model& m, bool all, size_t i) {
  return all && m.dim == 3 && m.blocks3.is_slave(i);
}

// The numbers of all blocks, in the engine's order (a write given no `blocks=`).
std::vector<int> all_block_ids(const Model& m) {
  return m.dim == 3 ? m.blocks3.id : m.blocks.id;
}

// The commands that cycle, refused inside a callback (it runs between two cycles of one).
bool cycles(const std::string& text) {
  std::istringstream in(text);
  std::string line, word;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    if (words >> word && (word == "step" || word == "solve" || word == "call" || word == "restore"))
      return true;
  }
  return false;
}

// The models alive, for their results at exit.
std::set<PyModel*>& live_models() {
  static std::set<PyModel*> models;
  return models;
}

// How the program is ending: an uncaught exception (printed by now and kept as sys.last_value)
// is an error, named as file:line: Type: message at its innermost frame, or (KeyboardInterrupt)
// an interruption; {"completed", ""} otherwise.
std::pair<std::string, std::string> program_outcome() {
  const py::module_ sys = py::module_::import("sys");
  if (!py::hasattr(sys, "last_value") || sys.attr("last_value").is_none()) return {"completed", ""};
  const py::object e = sys.attr("last_value");
  if (py::isinstance(e, py::module_::import("builtins").attr("KeyboardInterrupt")))
    return {"interrupted", "SIGINT"};
  std::string where;
  py::object tb = sys.attr("last_traceback");
  while (!tb.is_none() && !tb.attr("tb_next").is_none()) tb = tb.attr("tb_next");
  if (!tb.is_none())
    where = py::str(tb.attr("tb_frame").attr("f_code").attr("co_filename")).cast<std::string>() +
            ":" + py::str(tb.attr("tb_lineno")).cast<std::string>() + ": ";
  const std::string type = py::str(py::type::of(e).attr("__name__"));
  return {"error", where + type + ": " + py::str(e).cast<std::string>()};
}

// At the program's exit (after an uncaught exception too), each model changed since its results
// were last written writes them, as a batch run does; after an uncaught exception every model
// writes its summary again, saying how the program ended.
void finish_all() {
  const auto [status, error] = program_outcome();
  for (PyModel* m : live_models()) {
    if (!m->owned || (!m->unwritten && status == "completed")) continue;
    if (status != "completed") m->interp->set_outcome(status, error);
    try {
      m->finish();
    } catch (const std::exception& e) {
      py::print("tessera:", e.what(), py::arg("file") = py::module_::import("sys").attr("stderr"));
    }
  }
}

}  // namespace

PyModel::PyModel(const std::string& out, bool be_quiet)
    : owned(std::make_unique<Interpreter>(out,
                                          [this](const std::string& s) {
                                            if (!quiet || s.find("warning") != std::string::npos)
                                              py::print(s, py::arg("flush") = true);
                                          })),
      interp(owned.get()),
      quiet(be_quiet) {
  interp->set_progress_interval(quiet ? 0.0 : 2.0);
  interp->set_observer([this](const Model& m) { observe(m); });
  live_models().insert(this);
}

PyModel::PyModel(Interpreter& borrowed) : interp(&borrowed) {}

PyModel::~PyModel() {
  live_models().erase(this);
}

void PyModel::finish() {
  interp->finish();
  unwritten = false;
}

void PyModel::run(const std::string& text) {
  if (in_callback && cycles(text))
    throw py::value_error("step, solve, call and restore cannot run inside an on_cycle callback");
  const auto [file, line] = caller();
  // Inside a callback the run around it keeps the model to go back to.
  std::optional<SavePoint> before;
  if (!in_callback) before = interp->save_point();
  pending.reset();
  unwritten = true;
  try {
    std::istringstream in(text);
    std::string one;
    for (int i = 0; std::getline(in, one); ++i) interp->execute(one, file, line + i);
    if (stop && stop->load() && !in_callback) {
      PyErr_SetNone(PyExc_KeyboardInterrupt);
      throw py::error_already_set();
    }
  } catch (const ScriptError&) {
    if (before) interp->restore(*before);
    if (pending) {
      // The callback's own exception, with its traceback.
      py::error_already_set e = std::move(*pending);
      pending.reset();
      e.restore();
      throw py::error_already_set();
    }
    throw;
  }
}

void PyModel::run_lines(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& l : lines) text += l + "\n";
  run(text);
}

void PyModel::observe(const Model& m) {
  // Stopped from the window: the run ends at its next check, as stopped (no callback now).
  if (stop && stop->load()) return;
  // Ctrl+C in Python stops the run (the model goes back to before it).
  if (m.cycle % 64 == 0 && PyErr_CheckSignals() != 0) {
    pending.emplace();
    throw std::runtime_error("interrupted");
  }
  for (const Callback& c : callbacks) {
    if (m.cycle % c.every != 0) continue;
    in_callback = true;
    try {
      c.fn(py::cast(this, py::return_value_policy::reference));
    } catch (py::error_already_set& e) {
      in_callback = false;
      const std::string what = e.what();
      pending.emplace(std::move(e));
      throw std::runtime_error("the on_cycle callback raised " + what);
    }
    in_callback = false;
  }
}

void define_module(py::module_& mod) {
  mod.doc() = "Tessera, a distinct element code: models, their cycle and results as numpy arrays";
  // ScriptError(RuntimeError) with the interpreter's text and its parts: file, line, message.
  // The class lives as long as the process (no reference is dropped at exit).
  static const py::handle script_error =
      py::exception<ScriptError>(mod, "ScriptError", PyExc_RuntimeError).release();
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ScriptError& e) {
      py::object err = script_error(e.what());
      err.attr("file") = e.file(), err.attr("line") = e.line(), err.attr("message") = e.message();
      PyErr_SetObject(script_error.ptr(), err.ptr());
    }
  });
  mod.attr("BONDED") = int(kBonded), mod.attr("SLIPPING") = int(kSlipping);
  mod.attr("TOUCHING") = int(kTouching), mod.attr("BROKEN") = int(kBroken);

  mod.def("out_dir", &default_out,
          "The results folder a Model writes to by default: that of `tessera --batch --out`, or "
          "<script>_out beside the running script");
  bind_arrays(mod);
  py::module_::import("atexit").attr("register")(py::cpp_function(&finish_all));

  const auto group = [](auto tag) {
    using G = decltype(tag);
    return [](py::object self) { return G{{std::move(self)}}; };
  };
  py::class_<PyModel>(mod, "Model", "A model: script commands, cycling, results as arrays")
      .def(py::init([](std::optional<std::string> out, std::optional<bool> quiet,
                       std::optional<int> threads) {
             // `tessera --batch` passes its --quiet and --threads as TESSERA_QUIET and
             // TESSERA_THREADS.
             const char* env_threads = std::getenv("TESSERA_THREADS");
             if (!threads && env_threads) threads = std::atoi(env_threads);
             if (threads) {
               if (*threads < 1 || *threads > 256)
                 throw py::value_error("threads= takes 1 to 256 worker threads");
               set_thread_count(*threads);
             }
             const char* env_quiet = std::getenv("TESSERA_QUIET");
             if (!quiet) quiet = env_quiet && std::string(env_quiet) == "1";
             return std::make_unique<PyModel>(out ? *out : default_out(), *quiet);
           }),
           py::arg("out") = py::none(), py::arg("quiet") = py::none(),
           py::arg("threads") = py::none())
      .def("command", &PyModel::run, py::arg("text"),
           "Runs script text (one or more lines); on an error raises ScriptError and leaves the "
           "model as it was")
      .def(
          "cycle",
          [](PyModel& s, int64_t n) {
            if (n < 0) throw py::value_error("cycle(n) takes a number of cycles n >= 0");
            s.run("step " + std::to_string(n));
          },
          py::arg("n"), "Runs n cycles")
      .def(
          "solve",
          [](PyModel& s, double ratio, int64_t cycles) {
            s.run("solve ratio=" + number(ratio) + " cycles=" + std::to_string(cycles));
            return s.interp->stages().back().converged;
          },
          py::arg("ratio") = 1e-5, py::arg("cycles") = 1000000,
          "Cycles until the unbalanced-force ratio is below `ratio`; returns whether it got there")
      .def(
          "on_cycle",
          [](PyModel& s, std::optional<py::function> fn, int64_t every) {
            if (!fn) return s.callbacks.clear();
            if (every < 1) throw py::value_error("on_cycle: every= must be at least 1");
            s.callbacks.push_back({*fn, static_cast<uint64_t>(every)});
          },
          py::arg("fn"), py::arg("every") = 1,
          "Calls fn(model) after every `every` cycles of a run; on_cycle(None) removes them all")
      .def(
          "set_velocity",
          [](PyModel& s, const py::array_t<double, py::array::c_style | py::array::forcecast>& v,
             std::optional<std::vector<int>> blocks,
             std::optional<py::array_t<double, py::array::c_style | py::array::forcecast>> omega) {
            const Model& m = s.model();
            const std::vector<int> ids = blocks ? *blocks : all_block_ids(m);
            const size_t d = m.dim, dm = m.dim == 3 ? 3 : 1;
            const std::vector<double> rows = rows_of(v, ids.size(), d, "set_velocity");
            const std::vector<double> turn =
                turn_rows(omega, ids.size(), dm, "set_velocity(omega=)");
            std::vector<std::string> lines;
            for (size_t i = 0; i < ids.size(); ++i) {
              if (later_piece_row(m, !blocks, i)) continue;
              std::string l = "velocity block=" + std::to_string(ids[i]);
              for (size_t k = 0; k < d; ++k)
                l += std::string(" v") + "xyz"[k] + "=" + number(rows[i * d + k]);
              if (!turn.empty() && dm == 1) l += " omega=" + number(turn[i]);
              if (!turn.empty() && dm == 3)
                for (size_t k = 0; k < 3; ++k)
                  l += std::string(" w") + "xyz"[k] + "=" + number(turn[i * 3 + k]);
              lines.push_back(l);
            }
            s.run_lines(lines);
          },
          py::arg("v"), py::arg("blocks") = py::none(), py::arg("omega") = py::none(),
          "Sets block velocities (rows for the blocks numbered, or all): the velocity of a free "
          "degree of freedom, the prescribed one of a fixed one (the 'velocity' command); "
          "omega, if given, the angular velocity (2D (n,) or a number, 3D (n, 3) world vector; "
          "a joined 3D body takes its first piece's row when all are given)")
      .def(
          "set_force",
          [](PyModel& s, const py::array_t<double, py::array::c_style | py::array::forcecast>& f,
             std::optional<std::vector<int>> blocks,
             std::optional<py::array_t<double, py::array::c_style | py::array::forcecast>> moment) {
            const Model& m = s.model();
            const std::vector<int> ids = blocks ? *blocks : all_block_ids(m);
            const size_t d = m.dim, dm = m.dim == 3 ? 3 : 1;
            const std::vector<double> rows = rows_of(f, ids.size(), d, "set_force");
            const std::vector<double> turn =
                turn_rows(moment, ids.size(), dm, "set_force(moment=)");
            std::vector<std::string> lines;
            for (size_t i = 0; i < ids.size(); ++i) {
              if (later_piece_row(m, !blocks, i)) continue;
              std::string l = "load block=" + std::to_string(ids[i]);
              for (size_t k = 0; k < d; ++k)
                l += std::string(" f") + "xyz"[k] + "=" + number(rows[i * d + k]);
              if (!turn.empty() && dm == 1) l += " moment=" + number(turn[i]);
              if (!turn.empty() && dm == 3)
                for (size_t k = 0; k < 3; ++k)
                  l += std::string(" m") + "xyz"[k] + "=" + number(turn[i * 3 + k]);
              lines.push_back(l);
            }
            s.run_lines(lines);
          },
          py::arg("f"), py::arg("blocks") = py::none(), py::arg("moment") = py::none(),
          "Constant loads at the centroids of rigid blocks (rows for the blocks numbered, or "
          "all): force (n, dim) and, if given, moment (2D (n,) or a number, 3D (n, 3)); they "
          "replace the blocks' loads before, a moment not given staying as it was (the 'load' "
          "command; a joined 3D body takes its first piece's row when all are given)")
      .def(
          "set_node_force",
          [](PyModel& s, const py::array_t<double, py::array::c_style | py::array::forcecast>& f,
             std::optional<std::vector<int64_t>> nodes) {
            Model& m = s.model();
            const size_t count = m.dim == 3 ? m.continuum3.node_count() : m.continuum.node_count();
            std::vector<int64_t> idx = nodes ? *nodes : std::vector<int64_t>{};
            if (!nodes)
              for (size_t n = 0; n < count; ++n) idx.push_back(static_cast<int64_t>(n));
            for (int64_t n : idx)
              if (n < 0 || static_cast<size_t>(n) >= count)
                throw py::index_error("set_node_force: node " + std::to_string(n) +
                                      " is not a row of Model.nodes (" + std::to_string(count) +
                                      " nodes)");
            const size_t d = m.dim;
            const std::vector<double> rows = rows_of(f, idx.size(), d, "set_node_force");
            s.unwritten = true;
            for (size_t i = 0; i < idx.size(); ++i)
              for (size_t k = 0; k < d; ++k) {
                const auto n = static_cast<size_t>(idx[i]);
                const int j = static_cast<int>(k);
                if (d == 3)
                  m.continuum3.applied[n][j] = rows[i * d + k];
                else
                  m.continuum.applied[n][j] = rows[i * d + k];
              }
          },
          py::arg("f"), py::arg("nodes") = py::none(),
          "Sets the constant load (N) on nodes of zoned blocks (rows of Model.nodes, or all), "
          "replacing what 'boundary stress' put there")
      .def(
          "set_joint",
          [](PyModel& s, const std::string& name, const py::kwargs& kw) {
            s.run("joint define " + name + keywords(kw));
          },
          py::arg("name"),
          "Defines or changes a set of joint properties: set_joint('rough', friction=30) is "
          "'joint define rough friction=30'")
      .def(
          "set_material",
          [](PyModel& s, const std::string& name, const py::kwargs& kw) {
            s.run("material define " + name + keywords(kw));
          },
          py::arg("name"), "Defines a material: 'material define NAME key=value ...'")
      .def(
          "set_gravity",
          [](PyModel& s, const py::array_t<double, py::array::c_style | py::array::forcecast>& g) {
            const std::vector<double> v = rows_of(g, 1, s.model().dim, "set_gravity");
            std::string l = "gravity";
            for (double x : v) l.append(" ").append(number(x));
            s.run(l);
          },
          py::arg("g"), "Sets the gravitational acceleration (m/s^2), a vector of the dimension")
      .def(
          "set_table",
          [](PyModel& s, const std::string& name, const std::vector<double>& time,
             const std::vector<double>& value) {
            try {
              s.interp->set_table(name, Table{time, value});
            } catch (const std::invalid_argument& e) {
              throw py::value_error(e.what());
            }
          },
          py::arg("name"), py::arg("time"), py::arg("value"),
          "Defines (or replaces) a table of values at increasing times, for table=NAME")
      .def(
          "set_variable",
          [](PyModel& s, const std::string& name, double v) {
            s.run("set " + name + " = " + number(v));
          },
          py::arg("name"), py::arg("value"), "Sets a script variable")
      .def(
          "variable",
          [](const PyModel& s, const std::string& name) {
            try {
              return s.interp->variable(name);
            } catch (const std::out_of_range&) {
              throw py::key_error("no script variable '" + name + "'");
            }
          },
          py::arg("name"), "The value of a script variable")
      .def("finish", &PyModel::finish,
           "Writes history.csv, a final VTK snapshot and summary.json into the results folder "
           "(done at the program's exit for every model changed since it last wrote them)")
      .def("__enter__", [](py::object self) { return self; })
      .def("__exit__",
           [](PyModel& s, py::object, py::object, py::object) {
             s.finish();
             return false;
           })
      .def_property_readonly("dim", [](PyModel& s) { return int(s.model().dim); })
      .def_property_readonly(
          "cycles", [](PyModel& s) { return s.model().cycle; }, "cycles run so far")
      .def_property_readonly("time", [](PyModel& s) { return s.model().time; })
      .def_property_readonly("dt",
                             [](PyModel& s) {
                               // The next cycle's step, formed now if the model changed since
                               // the last (before the first cycle it would read 0).
                               Model& m = s.model();
                               if (m.dt_dirty && m.block_count() > 0) prepare(m);
                               return m.dt;
                             })
      .def_property_readonly("ratio", [](PyModel& s) { return s.model().ratio; })
      .def_property_readonly("groups", [](PyModel& s) { return s.model().groups; })
      .def_property_readonly("out", [](PyModel& s) { return s.interp->out_dir(); })
      .def_property_readonly("blocks", group(BlockGroup{}))
      .def_property_readonly("contacts", group(ContactGroup{}))
      .def_property_readonly("subcontacts", group(SubContactGroup{}))
      .def_property_readonly("zones", group(ZoneGroup{}))
      .def_property_readonly("nodes", group(NodeGroup{}))
      .def_property_readonly("histories", group(HistoryGroup{}));
}

}  // namespace tessera::python
