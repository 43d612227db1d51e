// bench dpd's LAMMPS side (study/lammps_bench.hpp): the loop time read from a fixed LAMMPS log, the launcher's
// lookup (a bad --lammps is refused, an absent LAMMPS is "not found", never a path that is not there), and the
// input script's scene.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "dpdrng/common/error.hpp"
#include "dpdrng/study/lammps_bench.hpp"
#include "../temp_dir.hpp"

namespace dpdrng_test::study_test_lammps_bench {

using namespace dpdrng::study::lammps;

// The end of a LAMMPS log of two runs (equilibration, then production), as the 29 Sep 2021 release writes it;
// the figures are made up.
constexpr const char* kLog = R"(Step Temp 
       0            1 
      50    1.1234567 
Loop time of 0.891011 on 1 procs for 50 steps with 24000 atoms

Performance: 193937.224 tau/day, 56.116 timesteps/s
99.8% CPU use with 1 MPI tasks x 1 OpenMP threads

Step Temp 
      50    1.1234567 
     150    1.0543210 
Loop time of 3.25 on 2 procs for 100 steps with 24000 atoms

Performance: 106338.462 tau/day, 30.769 timesteps/s
199.2% CPU use with 1 MPI tasks x 2 OpenMP threads
Total wall time: 0:00:04
)";

TEST(LammpsLog, TheLastLoopTimeIsTheProductionRun) {
  const auto t = last_loop_time(kLog);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(t->seconds, 3.25);
  EXPECT_EQ(t->procs, 2);
  EXPECT_EQ(t->steps, 100);
  EXPECT_EQ(t->atoms, 24000);
  EXPECT_EQ(t->particle_steps_per_s(), 24000.0 * 100 / 3.25);
}

TEST(LammpsLog, NoLoopTimeIsNone) {
  EXPECT_FALSE(last_loop_time("").has_value());
  EXPECT_FALSE(last_loop_time("ERROR: Unrecognized pair style 'dpd/hash' (src/force.cpp:279)\n").has_value());
  // Cut short, not at a line's start, or not numbers: not a loop time.
  EXPECT_FALSE(last_loop_time("Loop time of 3.25 on 1 procs for 100 steps\n").has_value());
  EXPECT_FALSE(last_loop_time("print 'Loop time of 3.25 on 1 procs for 100 steps with 9 atoms'\n").has_value());
  EXPECT_FALSE(last_loop_time("Loop time of x on 1 procs for 100 steps with 9 atoms\n").has_value());
  EXPECT_FALSE(last_loop_time("Loop time of 0 on 1 procs for 100 steps with 9 atoms\n").has_value());
}

TEST(LammpsLog, ALaterBrokenLineDoesNotRevertToAnEarlierRun) {
  const std::string log = std::string(kLog) + "Loop time of 1.5 on 1 procs for\n";
  EXPECT_FALSE(last_loop_time(log).has_value());
}

void make_file(const std::filesystem::path& p, bool executable) {
  std::ofstream(p) << "#!/bin/sh\n";
  ::chmod(p.c_str(), executable ? 0755 : 0644);
}

TEST(LammpsLauncher, AbsentIsNotFound) {
  const TempDir dir;
  EXPECT_FALSE(find_launcher("", {(dir.path / "build/lammps/lmp_dpdrng").string()}, "").has_value());
  EXPECT_FALSE(find_launcher("", {}, dir.path.string() + "::/nonexistent").has_value());
  make_file(dir.path / "lmp_dpdrng", false);  // there, but not executable
  EXPECT_FALSE(find_launcher("", {(dir.path / "lmp_dpdrng").string()}, dir.path.string()).has_value());
}

TEST(LammpsLauncher, CandidatesBeforePath) {
  const TempDir dir;
  std::filesystem::create_directories(dir.path / "a");
  std::filesystem::create_directories(dir.path / "b");
  make_file(dir.path / "a/lmp_dpdrng", true);
  make_file(dir.path / "b/lmp_dpdrng", true);
  const std::string a = (dir.path / "a/lmp_dpdrng").string(), b = (dir.path / "b/lmp_dpdrng").string();
  EXPECT_EQ(find_launcher("", {"/nonexistent/lmp_dpdrng", a}, (dir.path / "b").string()), a);
  EXPECT_EQ(find_launcher("", {"/nonexistent/lmp_dpdrng"}, "/nonexistent:" + (dir.path / "b").string()), b);
  EXPECT_EQ(find_launcher(b, {a}, ""), b);
}

TEST(LammpsLauncher, ABadExplicitPathIsRefused) {
  const TempDir dir;
  EXPECT_THROW(find_launcher((dir.path / "nope").string(), {}, ""), dpdrng::InputError);
  make_file(dir.path / "plain", false);
  EXPECT_THROW(find_launcher((dir.path / "plain").string(), {}, ""), dpdrng::InputError);
  EXPECT_THROW(find_launcher(dir.path.string(), {}, ""), dpdrng::InputError);  // a folder
}

TEST(LammpsScene, TheScriptRunsTheWaterScene) {
  Scene s;
  s.particles = 3000, s.gamma = 4.5, s.equilibrate = 50, s.steps = 100;
  const std::string in = input_script(s, hash_style(s, "tea32", 1, "gauss", "halves", 7));
  for (const char* line : {"\ncreate_atoms 1 random 3000 2021 NULL\n", "\npair_style dpd/hash 1 1 tea32 1 distance "
                           "gauss halves 7\n", "\npair_coeff 1 1 25 4.5 1\n", "\ntimestep 0.04\n", "\ncomm_modify vel yes\n",
                           "\nrun 50\nrun 100\n"})
    EXPECT_NE(in.find(line), std::string::npos) << line << " not in\n" << in;
  // 3000 beads at rho = 3: a cube of side 10.
  EXPECT_NE(in.find("\nregion box block 0 10 0 10 0 10\n"), std::string::npos) << in;
  EXPECT_EQ(own_style(s, 7), "dpd 1 1 8");
}

}  // namespace dpdrng_test::study_test_lammps_bench
