#include "app/commands.hpp"

namespace shotlab {

// The work-precision bench (issue 4) registers here.
void add_bench_command(CLI::App&) {}

}  // namespace shotlab
