// The extension module `tessera` that python3 imports (the window embeds the same contents).
#include "bindings.hpp"

PYBIND11_MODULE(tessera, mod) {
  tessera::python::define_module(mod);
}
