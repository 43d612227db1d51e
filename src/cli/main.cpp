// dpdrng: thin glue from the command line to the library; every subcommand registers itself (registry.hpp) and
// run_cli (run.hpp) handles the command line.
#include <unistd.h>

#include <cstdlib>

#include "dpdrng/cli/run.hpp"
#include "dpdrng/study/library_init.hpp"

namespace dpdrng::cli::main_entry {
namespace {

// ~0.1 ms of spinning where a pause takes 40 ns (Intel Xeon family 6 model 167): longer than most waits at a barrier of
// the cells loop, where a thread that went to sleep costs the step a wake-up, and short against a scheduler's
// slice, which a thread spinning beside another process's busy loop would burn. Systems small enough for
// each wait to matter more than that run on one thread anyway (dpd::team_threads).
constexpr const char* kGompSpinCount = "3000";

// libgomp reads its wait policy once, when it is loaded, before main(): unless OMP_WAIT_POLICY or GOMP_SPINCOUNT
// says otherwise, a thread waiting at a barrier spins 300 000 pause instructions before it sleeps, ~12 ms where
// a pause takes 40 ns. On a machine shared with other work the spinning thread holds a core that a
// preempted team-mate needs, and a two-thread run ends up slower than one thread. Unless the user chose a
// policy, the process therefore runs itself again, once, with a short spin (kGompSpinCount).
void bound_openmp_spin(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) return;
  if (setenv("GOMP_SPINCOUNT", kGompSpinCount, 1) != 0) return;
  execv("/proc/self/exe", argv);  // returns only if that failed: run on with libgomp's default
  unsetenv("GOMP_SPINCOUNT");
}

}  // namespace
}  // namespace dpdrng::cli::main_entry

int main(int argc, char** argv) {
  dpdrng::cli::main_entry::bound_openmp_spin(argv);
  dpdrng::study::init_libraries();
  return dpdrng::cli::run_cli(argc, argv, dpdrng::cli::RunMode::run);
}
