#pragma once
// The water scene of `bench dpd` run in LAMMPS (lmp_dpdrng, lammps/build.sh), so that a speed claim against
// LAMMPS is measured on the same CPU in the same run: LAMMPS's own `pair_style dpd` and `pair_style dpd/hash`
// (dpdrng's noise in LAMMPS) on the scene dpdrng's engine runs, timed by LAMMPS's own loop time.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dpdrng::study::lammps {

// LAMMPS's summary of a run: "Loop time of X on P procs for S steps with N atoms" (P counts MPI ranks × OpenMP
// threads).
struct LoopTime {
  double seconds = 0;
  int procs = 0;
  std::int64_t steps = 0;
  std::int64_t atoms = 0;
  double particle_steps_per_s() const { return double(atoms) * double(steps) / seconds; }
};

// The last loop-time line of a log (a log holds one per `run`; the last is the production run); nullopt when
// the log has none, or the line does not read as one.
std::optional<LoopTime> last_loop_time(std::string_view log);

// The launcher to use: `explicit_path` when given (InputError unless it is an executable file); else the first
// executable of `candidates`; else `lmp_dpdrng` on `search_path` (PATH's format). nullopt: LAMMPS not built.
std::optional<std::string> find_launcher(const std::string& explicit_path, const std::vector<std::string>& candidates,
                                         const std::string& search_path);

// The scene: N beads at density ρ in a cube, one bead type, a, γ, k_BT, r_c, Δt, `equilibrate` untimed steps,
// then `steps` timed; velocity Verlet (GW-MVV with λ = 0.5, as dpdrng's mvv), neighbour skin 0.3 checked every
// step. `pair_style` is the style line after the word: "dpd T rc seed" or "dpd/hash T rc gen rounds ...".
struct Scene {
  int particles = 24000;
  double density = 3.0, a = 25.0, gamma = 4.5, kT = 1.0, rc = 1.0, dt = 0.04;
  std::int64_t equilibrate = 50, steps = 100;
  std::uint64_t init_seed = 2021;
};
std::string input_script(const Scene& scene, const std::string& pair_style);

// The style lines compared: LAMMPS's own, and dpd/hash with a dpdrng generator under distance seeding.
std::string own_style(const Scene& scene, std::uint64_t seed);
std::string hash_style(const Scene& scene, const std::string& generator, int rounds, const std::string& distribution,
                       const std::string& feed, std::uint64_t seed);

// Runs the scene once on one MPI rank (threads > 1: LAMMPS's OPENMP package, -sf omp -pk omp threads) in a
// scratch folder of its own. Throws std::runtime_error with the reason (LAMMPS's ERROR line, or how it ended)
// when it fails or its log has no loop time of the scene's atoms and steps.
LoopTime run_scene(const std::string& launcher, const Scene& scene, const std::string& pair_style, int threads);

}  // namespace dpdrng::study::lammps
