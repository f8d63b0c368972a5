// `tessera --batch study.py`: the Python interpreter the module was built for runs the file as a
// child process, with the module's folder on PYTHONPATH and the results folder, threads and
// quietness in TESSERA_OUT, TESSERA_THREADS and TESSERA_QUIET (read by tessera.Model).
//
// A child process rather than an embedded interpreter: the program links no libpython, the
// script runs exactly as `python3 study.py` would (its own sys.argv, signals, exit status), and
// the engine is loaded once, by the module.
#include "python_batch.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <vector>

extern char** environ;

namespace tessera::app {

#ifndef TESSERA_PYTHON
int run_python_batch(const std::string& script, const std::string&, int, bool) {
  std::cerr << script
            << ": this tessera was built without the Python module (install pybind11-dev, "
               "python3-dev and python3-numpy, e.g. with scripts/install-deps.sh, and build again)"
            << std::endl;
  return 1;
}
#else
namespace {
volatile std::sig_atomic_t g_child = 0;
// SIGTERM goes on to the script, which stops between two cycles (KeyboardInterrupt-like).
extern "C" void forward_signal(int sig) {
  if (g_child > 0) kill(static_cast<pid_t>(g_child), sig);
}
}  // namespace

int run_python_batch(const std::string& script, const std::string& out_dir, int threads,
                     bool quiet) {
  // The environment, with the module's folder ahead of any PYTHONPATH already set.
  std::vector<std::string> env;
  std::string path = TESSERA_PYTHON_DIR;
  for (char** e = environ; *e; ++e) {
    const std::string var = *e;
    if (var.rfind("PYTHONPATH=", 0) == 0)
      path.append(":").append(var, 11);
    else if (var.rfind("TESSERA_OUT=", 0) && var.rfind("TESSERA_THREADS=", 0) &&
             var.rfind("TESSERA_QUIET=", 0))
      env.push_back(var);
  }
  env.push_back("PYTHONPATH=" + path);
  env.push_back("TESSERA_OUT=" + out_dir);
  env.push_back("TESSERA_THREADS=" + std::to_string(threads));
  env.push_back(std::string("TESSERA_QUIET=") + (quiet ? "1" : "0"));
  std::vector<char*> envp;
  for (std::string& v : env) envp.push_back(v.data());
  envp.push_back(nullptr);
  std::string python = TESSERA_PYTHON, file = script;
  char* argv[] = {python.data(), file.data(), nullptr};

  // The child starts with default handlers (so Python turns Ctrl+C into KeyboardInterrupt);
  // this process leaves Ctrl+C to it and passes SIGTERM on.
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF);
  std::signal(SIGINT, SIG_IGN);
  pid_t pid = 0;
  const int err = posix_spawn(&pid, python.c_str(), nullptr, &attr, argv, envp.data());
  posix_spawnattr_destroy(&attr);
  if (err != 0) {
    std::cerr << "tessera: cannot start " << python << ": " << std::strerror(err) << std::endl;
    return 1;
  }
  g_child = pid;
  std::signal(SIGTERM, forward_signal);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return 1;
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  const int code = WEXITSTATUS(status);
  if (code == 0 && !quiet) std::cout << "results in " << out_dir << std::endl;
  return code;
}
#endif

}  // namespace tessera::app
