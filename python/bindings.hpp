// The Python module's model object (module.cpp) and its array groups (arrays.cpp).
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tessera/script/script.hpp"

namespace tessera::python {

namespace py = pybind11;

// A model and the interpreter that runs its commands, as Python's tessera.Model.
struct PyModel {
  struct Callback {
    py::function fn;
    uint64_t every = 1;
  };
  PyModel(const std::string& out, bool quiet);
  // The model of an interpreter someone else owns and observes (the window's console): its
  // owner calls observe() after each cycle and writes its results.
  explicit PyModel(Interpreter& borrowed);
  ~PyModel();
  PyModel(const PyModel&) = delete;
  PyModel& operator=(const PyModel&) = delete;
  // Runs script text (one or more lines) as if it stood at file:line (the caller's place in
  // Python); on an error the model, variables and stages are put back as they were.
  void run(const std::string& text);
  // Runs lines made by the module itself (writes), as one undoable unit.
  void run_lines(const std::vector<std::string>& lines);
  // Called after every cycle of a step or solve: the Python callbacks that are due.
  void observe(const Model& m);
  Model& model() { return interp->model(); }
  // Writes the results folder (Interpreter::finish).
  void finish();

  std::unique_ptr<Interpreter> owned;  // null when borrowed
  Interpreter* interp = nullptr;
  std::vector<Callback> callbacks;
  // The Python error a callback raised during a run, raised again once the run has unwound.
  std::optional<py::error_already_set> pending;
  // The window's Stop (borrowed models): a call that finds it set raises KeyboardInterrupt, so a
  // Python loop of runs ends with the run it stopped.
  const std::atomic<bool>* stop = nullptr;
  bool in_callback = false;
  bool quiet = false;
  // Changed since its results were last written: they are written at the program's exit.
  bool unwritten = false;
};

// An array group (m.blocks, m.contacts, ...): the Python model it belongs to.
struct Group {
  py::object owner;
  PyModel& self() const { return owner.cast<PyModel&>(); }
  const Model& model() const { return self().model(); }
};
struct BlockGroup : Group {};
struct ContactGroup : Group {};
struct SubContactGroup : Group {};
struct ZoneGroup : Group {};
struct NodeGroup : Group {};
struct HistoryGroup : Group {};

// Defines the array groups' classes (arrays.cpp).
void bind_arrays(py::module_& m);

// Defines the module's contents (module.cpp): the extension module `tessera` and the window's
// embedded one are the same.
void define_module(py::module_& mod);

}  // namespace tessera::python
