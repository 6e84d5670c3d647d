#include "plot_script.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <vector>

#include "app/paths.hpp"

extern char** environ;

namespace shotlab {
namespace {

// Runs args[0] (looked up on PATH unless it holds a '/') with the other arguments and waits for it: its exit status,
// or -1 when it could not start or was ended by a signal. No shell, so no quoting of odd paths is needed. quiet: its
// output goes to /dev/null.
int run_program(const std::vector<std::string>& args, bool quiet) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (quiet) {
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  }
  pid_t pid = 0;
  const int failed = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (failed) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Debian's python3-matplotlib lives in /usr/bin/python3's packages, which a python3 from pyenv or a venv that comes
// first on PATH does not see: hence the second candidate.
std::string python_with_matplotlib() {
  std::vector<std::string> candidates{"python3", "/usr/bin/python3"};
  if (const char* chosen = std::getenv("SHOTLAB_PYTHON")) candidates = {chosen};
  for (const std::string& python : candidates)
    if (run_program({python, "-c", "import matplotlib"}, true) == 0) return python;
  return "";
}

}  // namespace

bool run_plot_script(const std::string& script, const std::vector<std::string>& args, const std::string& command) {
  const std::string path = data_root() + "/scripts/" + script;
  const bool have_script = std::filesystem::is_regular_file(path);
  const std::string python = have_script ? python_with_matplotlib() : "";
  std::string shown;
  for (const std::string& a : args) shown += " " + a;
  if (python.empty()) {
    std::cerr << command << ": figures not drawn (" << (have_script ? "no python3 with matplotlib" : "no " + path)
              << "); draw it with `python3 " << path << shown
              << "` (needs matplotlib; Debian: apt-get install python3-matplotlib)" << std::endl;
    return true;
  }
  std::cout.flush();  // our lines first, then the script's
  std::vector<std::string> argv{python, path, "--"};
  argv.insert(argv.end(), args.begin(), args.end());
  if (run_program(argv, false) == 0) return true;
  std::cerr << command << ": " << path << " failed on" << shown << " (the data files are written)" << std::endl;
  return false;
}

bool draw_figures(const std::string& out_dir) { return run_plot_script("bench_plots.py", {out_dir}, "shotlab bench"); }

}  // namespace shotlab
