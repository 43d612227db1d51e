// The water scene in LAMMPS for bench dpd (lammps_bench.hpp).
#include "dpdrng/study/lammps_bench.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "dpdrng/common/error.hpp"

extern char** environ;

namespace dpdrng::study::lammps {
namespace {

namespace fs = std::filesystem;

bool is_executable_file(const std::string& path) {
  struct stat st {};
  return !path.empty() && ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(path.c_str(), X_OK) == 0;
}

// One loop-time line, after "Loop time of ": "X on P procs for S steps with N atoms".
std::optional<LoopTime> parse_loop_line(const std::string& rest) {
  std::istringstream in(rest);
  LoopTime t;
  std::string on, procs, for_, steps, with, atoms;
  if (!(in >> t.seconds >> on >> t.procs >> procs >> for_ >> t.steps >> steps >> with >> t.atoms >> atoms))
    return std::nullopt;
  if (on != "on" || procs != "procs" || for_ != "for" || steps != "steps" || with != "with" || atoms != "atoms")
    return std::nullopt;
  if (!(std::isfinite(t.seconds) && t.seconds > 0) || t.procs < 1 || t.steps < 1 || t.atoms < 1) return std::nullopt;
  return t;
}

// The shortest text that reads back as the same double (LAMMPS parses it with strtod).
std::string num(double v) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, end);
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// LAMMPS's reason for stopping: its first ERROR line, else the log's last line.
std::string failure_reason(const std::string& log) {
  std::istringstream in(log);
  std::string line, last;
  while (std::getline(in, line)) {
    if (line.rfind("ERROR", 0) == 0) return line;
    if (!line.empty()) last = line;
  }
  return last.empty() ? "an empty log" : "log ends: " + last;
}

// A scratch folder removed when the run is over.
struct ScratchDir {
  ScratchDir() {
    std::string tmpl = (fs::temp_directory_path() / "dpdrng-lammps-XXXXXX").string();
    if (::mkdtemp(tmpl.data()) == nullptr) throw std::runtime_error("LAMMPS: cannot make a scratch folder in " + tmpl);
    path = tmpl;
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  fs::path path;
};

// Runs argv[0] with argv, standard output and error to `out`; its exit status, or -1 if it did not exit.
int spawn_and_wait(const std::vector<std::string>& args, const fs::path& out) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("LAMMPS: cannot start " + args[0] + ": " + std::strerror(rc));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error("LAMMPS: waitpid failed");
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

std::optional<LoopTime> last_loop_time(std::string_view log) {
  constexpr std::string_view kLead = "Loop time of ";
  std::optional<LoopTime> last;
  std::size_t pos = 0;
  while ((pos = log.find(kLead, pos)) != std::string_view::npos) {
    const bool line_start = pos == 0 || log[pos - 1] == '\n';
    const std::size_t end = std::min(log.find('\n', pos), log.size());
    const std::string rest(log.substr(pos + kLead.size(), end - pos - kLead.size()));
    if (line_start) last = parse_loop_line(rest);
    pos = end;
  }
  return last;
}

std::optional<std::string> find_launcher(const std::string& explicit_path, const std::vector<std::string>& candidates,
                                         const std::string& search_path) {
  if (!explicit_path.empty()) {
    if (!is_executable_file(explicit_path))
      throw InputError("--lammps " + explicit_path + ": not an executable file (lammps/build.sh builds lmp_dpdrng)");
    return explicit_path;
  }
  for (const auto& c : candidates)
    if (is_executable_file(c)) return c;
  std::istringstream dirs(search_path);
  for (std::string dir; std::getline(dirs, dir, ':');) {
    if (dir.empty()) continue;
    const std::string c = (fs::path(dir) / "lmp_dpdrng").string();
    if (is_executable_file(c)) return c;
  }
  return std::nullopt;
}

std::string input_script(const Scene& s, const std::string& pair_style) {
  std::ostringstream o;
  const std::string side = num(std::cbrt(double(s.particles) / s.density));
  o << "units lj\natom_style atomic\ndimension 3\nboundary p p p\nnewton on\ncomm_modify vel yes\n"
    << "region box block 0 " << side << " 0 " << side << " 0 " << side << "\n"
    << "create_box 1 box\n"
    << "create_atoms 1 random " << s.particles << " " << s.init_seed << " NULL\n"
    << "mass 1 1.0\n"
    << "velocity all create " << num(s.kT) << " " << s.init_seed << " loop geom\n"
    << "pair_style " << pair_style << "\n"
    << "pair_coeff 1 1 " << num(s.a) << " " << num(s.gamma) << " " << num(s.rc) << "\n"
    << "neighbor 0.3 bin\nneigh_modify every 1 delay 0 check yes\n"
    << "timestep " << num(s.dt) << "\nfix nve all nve\n"
    // Thermo output only at the ends of each run: the timed steps compute no pressure that dpdrng's do not.
    << "thermo_style custom step temp\nthermo " << std::max<std::int64_t>(s.steps, s.equilibrate) << "\n"
    << "run " << s.equilibrate << "\n"
    << "run " << s.steps << "\n";
  return o.str();
}

std::string own_style(const Scene& s, std::uint64_t seed) {
  // RanMars takes a seed in 1 .. 900 000 000.
  return "dpd " + num(s.kT) + " " + num(s.rc) + " " + std::to_string(1 + seed % 900'000'000);
}

std::string hash_style(const Scene& s, const std::string& generator, int rounds, const std::string& distribution,
                       const std::string& feed, std::uint64_t seed) {
  return "dpd/hash " + num(s.kT) + " " + num(s.rc) + " " + generator + " " + std::to_string(rounds) + " distance " +
         distribution + " " + feed + " " + std::to_string(seed);
}

LoopTime run_scene(const std::string& launcher, const Scene& scene, const std::string& pair_style, int threads) {
  const ScratchDir dir;
  const fs::path input = dir.path / "in.bench", log = dir.path / "log.lammps", out = dir.path / "out";
  {
    std::ofstream f(input);
    f << input_script(scene, pair_style);
    if (!f) throw std::runtime_error("LAMMPS: cannot write " + input.string());
  }
  std::vector<std::string> args{launcher, "-in", input.string(), "-log", log.string(), "-screen", "none"};
  if (threads > 1) args.insert(args.end(), {"-sf", "omp", "-pk", "omp", std::to_string(threads)});
  const int status = spawn_and_wait(args, out);
  const std::string text = slurp(log);
  if (status != 0) {
    const std::string why = text.empty() ? failure_reason(slurp(out)) : failure_reason(text);
    throw std::runtime_error("LAMMPS (" + pair_style + ") failed: " + why);
  }
  const auto t = last_loop_time(text);
  if (!t || t->steps != scene.steps || t->atoms != scene.particles)
    throw std::runtime_error("LAMMPS (" + pair_style + "): its log has no loop time of " +
                             std::to_string(scene.steps) + " steps with " + std::to_string(scene.particles) + " atoms");
  return *t;
}

}  // namespace dpdrng::study::lammps
