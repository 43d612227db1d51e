// bench dpd beside LAMMPS (bench_dpd_lammps.hpp).
#include "bench_dpd_lammps.hpp"

#include <unistd.h>

#include <cstdlib>
#include <exception>
#include <iomanip>
#include <iostream>

#include "dpdrng/stats/summary.hpp"

namespace dpdrng::cli::bench_dpd_lammps {
namespace {

namespace lmp = study::lammps;

study::lammps::Scene scene_of(const dpd::WaterConfig& c) {
  lmp::Scene s;
  s.particles = c.particles;
  s.density = c.density, s.a = c.a, s.gamma = c.gamma, s.kT = c.kT, s.rc = c.rc, s.dt = c.dt;
  s.equilibrate = c.equilibrate;
  s.steps = c.steps - c.equilibrate;
  s.init_seed = c.init_seed;
  return s;
}

void progress(const std::string& what) {
  if (isatty(STDERR_FILENO)) std::cerr << "\r\033[K" << what << std::flush;
}

double per_second(const Side& s, const std::vector<double>& t) {
  return double(s.scene.particles) * double(s.scene.steps) / stats::median(t);
}

}  // namespace

std::optional<std::string> locate(const std::string& explicit_path, bool disabled, std::string& why) {
  if (disabled) {
    why = kDisabled;
    return std::nullopt;
  }
  const char* path = std::getenv("PATH");
  auto found = lmp::find_launcher(explicit_path, {"build/lammps/lmp_dpdrng"}, path ? path : "");
  if (!found) why = kNotBuilt;
  return found;
}

Side not_applicable(const std::string& label, const std::string& why) {
  Side s;
  s.label = label;
  s.not_applicable = why;
  return s;
}

Side measure(const std::string& label, const std::string& launcher, const dpd::WaterConfig& cfg,
             const std::string& distribution, const std::string& feed, int threads, int repeat,
             const std::function<double()>& dpdrng_round) {
  Side s;
  s.label = label;
  s.launcher = launcher;
  s.scene = scene_of(cfg);
  s.threads = threads;
  s.own_style = lmp::own_style(s.scene, cfg.seed);
  s.hash_style = lmp::hash_style(s.scene, "tea32", 1, distribution, feed, cfg.seed);
  try {
    for (int r = 0; r < repeat; ++r) {
      const std::string round = ", round " + std::to_string(r + 1) + " of " + std::to_string(repeat);
      progress("bench dpd: " + label + " beside LAMMPS, dpdrng" + round);
      s.dpdrng_s.push_back(dpdrng_round());
      progress("bench dpd: " + label + " beside LAMMPS, pair_style dpd" + round);
      s.own_s.push_back(lmp::run_scene(launcher, s.scene, s.own_style, threads).seconds);
      progress("bench dpd: " + label + " beside LAMMPS, pair_style dpd/hash" + round);
      s.hash_s.push_back(lmp::run_scene(launcher, s.scene, s.hash_style, threads).seconds);
    }
  } catch (const std::runtime_error& e) {
    // The measured table stands; the comparison says why it has no figures.
    s.not_applicable = e.what();
    return s;
  }
  s.dpdrng_ps = per_second(s, s.dpdrng_s), s.own_ps = per_second(s, s.own_s), s.hash_ps = per_second(s, s.hash_s);
  return s;
}

void print(const Side& s) {
  if (!s.measured()) {
    std::cout << "\n" << s.label << " beside LAMMPS: not applicable: " << s.not_applicable;
    if (s.not_applicable == kNotBuilt) std::cout << " (lammps/build.sh builds build/lammps/lmp_dpdrng; --lammps PATH)";
    std::cout << "\n";
    return;
  }
  const auto& sc = s.scene;
  std::cout << std::setprecision(4) << "\nbeside LAMMPS (" << s.launcher << "), " << s.label << ": " << sc.particles
            << " beads, rho " << sc.density << ", a " << sc.a << ", gamma " << sc.gamma << ", dt " << sc.dt << ", "
            << sc.equilibrate << " + " << sc.steps << " steps, 1 rank x " << s.threads
            << " thread(s); " << s.dpdrng_s.size() << " rounds of the three in turn, medians\n"
            << "  dpdrng tea32(1)                " << std::setw(12) << s.dpdrng_ps << " p-steps/s\n"
            << "  LAMMPS pair_style dpd          " << std::setw(12) << s.own_ps << " p-steps/s   dpdrng/LAMMPS "
            << s.dpdrng_ps / s.own_ps << "\n"
            << "  LAMMPS pair_style dpd/hash     " << std::setw(12) << s.hash_ps << " p-steps/s   dpdrng/LAMMPS "
            << s.dpdrng_ps / s.hash_ps << "\n"
            << "  dpd/hash (" << s.hash_style.substr(s.hash_style.find("tea32")) << ") step time / pair_style dpd's: "
            << s.own_ps / s.hash_ps << "\n";
}

nlohmann::json to_json(const Side& s) {
  if (!s.measured()) return {{"scene_label", s.label}, {"launcher", nullptr}, {"not_applicable", s.not_applicable}};
  const auto& sc = s.scene;
  return {{"scene_label", s.label},
          {"launcher", s.launcher},
          {"scene", {{"particles", sc.particles}, {"density", sc.density}, {"a", sc.a}, {"gamma", sc.gamma},
                     {"kT", sc.kT}, {"rc", sc.rc}, {"dt", sc.dt}, {"equilibrate", sc.equilibrate},
                     {"steps", sc.steps}}},
          {"threads", s.threads},
          {"own_style", "pair_style " + s.own_style},
          {"hash_style", "pair_style " + s.hash_style},
          {"dpdrng_seconds", s.dpdrng_s},
          {"own_seconds", s.own_s},
          {"hash_seconds", s.hash_s},
          {"dpdrng_particle_steps_per_s", s.dpdrng_ps},
          {"own_particle_steps_per_s", s.own_ps},
          {"hash_particle_steps_per_s", s.hash_ps},
          {"dpdrng_over_own", s.dpdrng_ps / s.own_ps},
          {"dpdrng_over_hash", s.dpdrng_ps / s.hash_ps},
          {"hash_step_time_over_own", s.own_ps / s.hash_ps}};
}

}  // namespace dpdrng::cli::bench_dpd_lammps
