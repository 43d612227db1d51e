#pragma once
// How many threads the engine's parallel regions run on. Every region asks for team_size(threads): the run's
// thread count, lowered while a TeamCap is in force on the thread that opens the region. Results do not depend
// on the team (every region's work is split so that any team gives the same bits), so the team is a choice of
// speed alone, and a run may change it from one step to the next: TeamGovernor does, from measured step times.
#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

namespace dpdrng::dpd {

// Below this many beads a run keeps to one thread. A step of the paper's 256-bead fluid takes ~0.15 ms; each of
// its parallel regions has to wake a team-mate, which costs tens of microseconds on an idle core and a
// scheduler's time slice (milliseconds) once another process holds that core.
inline constexpr std::size_t kTeamBeads = 1024;

// The threads a run of `beads` beads uses: `requested` (0: OpenMP's default), or 1 under `team_beads`.
int team_threads(int requested, std::size_t beads, std::size_t team_beads = kTeamBeads);

// The team a region asks for: `threads` (0: OpenMP's default), at most the cap in force on the calling thread.
int team_size(int threads);

// Caps the team of every engine region that the constructing thread opens while the cap lives; a cap inside
// another keeps the lower. Like OpenMP's own nthreads-var, the cap belongs to the thread, so runs on different
// threads keep their own.
class TeamCap {
 public:
  explicit TeamCap(int cap);
  ~TeamCap();
  TeamCap(const TeamCap&) = delete;
  TeamCap& operator=(const TeamCap&) = delete;

 private:
  int previous_;
};

// Chooses each step's team from the times of the steps before it. Beside a core that another process keeps busy,
// a team of two waits at every barrier for whichever thread the scheduler has paused, and can take longer than
// one thread; on a quiet machine the whole team is fastest. The governor runs the current team, times it, and now
// and then probes a neighbouring rung of the ladder threads, threads/2, …, 1 for a few steps; it moves when the
// probe is faster by more than kMargin. A probe of a slower team costs its excess time, so the next probe waits
// long enough that probing stays within kBudget of the run's time (after a move, as long as going back to the
// team it left would cost).
class TeamGovernor {
 public:
  static constexpr int kWindow = 8;        // steps of the current team that a probe is compared with
  static constexpr int kProbeSteps = 3;    // a probe's steps; its first (waking threads, warming caches) is not timed
  static constexpr double kMargin = 0.03;  // a probe must be this much faster to move
  static constexpr double kBudget = 0.01;  // the share of the run's time that probing a slower team may cost
  static constexpr std::int64_t kMaxInterval = 4096;  // steps between probes at most

  explicit TeamGovernor(int threads);  // threads resolved (> 0)

  int team() const { return probing_ ? rungs_[probe_rung_] : rungs_[rung_]; }  // for the next step
  void record(double seconds);  // the time of the step just run with team()

  // Steps run with each team size, and how often the governor moved.
  const std::map<int, std::int64_t>& steps_by_team() const { return steps_; }
  std::int64_t moves() const { return moves_; }

 private:
  void start_probe();
  void finish_probe();
  double current_mean() const;
  static std::int64_t wait_after(double r);  // steps before the next probe of a team r times as slow

  std::vector<int> rungs_;  // threads, threads/2, …, 1 (distinct)
  std::size_t rung_ = 0, probe_rung_ = 0;
  bool probing_ = false, probe_down_ = true;  // probes alternate downwards and upwards where both exist
  std::vector<double> recent_;                // the current team's last kWindow step times, a ring
  std::size_t next_ = 0;
  std::vector<double> probe_;
  int probe_step_ = 0;
  std::int64_t until_probe_ = kWindow;
  std::map<int, std::int64_t> steps_;
  std::int64_t moves_ = 0;
};

}  // namespace dpdrng::dpd
