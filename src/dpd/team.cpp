#include "dpdrng/dpd/team.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace dpdrng::dpd {

namespace {
thread_local int cap_in_force = 0;  // 0: none
}  // namespace

int team_threads(int requested, std::size_t beads, std::size_t team_beads) {
  if (beads < team_beads) return 1;
  return requested > 0 ? requested : omp_get_max_threads();
}

int team_size(int threads) {
  const int t = threads > 0 ? threads : omp_get_max_threads();
  return cap_in_force > 0 ? std::min(t, cap_in_force) : t;
}

// A cap inside another keeps the lower of the two.
TeamCap::TeamCap(int cap) : previous_(cap_in_force) {
  cap = std::max(cap, 1);
  cap_in_force = previous_ > 0 ? std::min(previous_, cap) : cap;
}

TeamCap::~TeamCap() { cap_in_force = previous_; }

TeamGovernor::TeamGovernor(int threads) {
  for (int t = std::max(threads, 1);; t /= 2) {
    rungs_.push_back(t);
    if (t == 1) break;
  }
  recent_.reserve(kWindow);
}

void TeamGovernor::record(double seconds) {
  ++steps_[team()];
  if (probing_) {
    if (probe_step_++ > 0) probe_.push_back(seconds);
    if (probe_step_ == kProbeSteps) finish_probe();
    return;
  }
  if (recent_.size() < std::size_t(kWindow))
    recent_.push_back(seconds);
  else
    recent_[next_] = seconds;
  next_ = (next_ + 1) % kWindow;
  if (rungs_.size() > 1 && --until_probe_ <= 0 && recent_.size() == std::size_t(kWindow)) start_probe();
}

void TeamGovernor::start_probe() {
  const bool can_down = rung_ + 1 < rungs_.size(), can_up = rung_ > 0;
  const bool down = can_down && (probe_down_ || !can_up);
  probe_down_ = !down;
  probe_rung_ = down ? rung_ + 1 : rung_ - 1;
  probing_ = true, probe_step_ = 0, probe_.clear();
}

double TeamGovernor::current_mean() const {
  return std::accumulate(recent_.begin(), recent_.end(), 0.0) / double(recent_.size());
}

// A team that took r times the current one's: its probe's kProbeSteps steps cost kProbeSteps·(r − 1) steps of
// the current team's time, so waiting that over kBudget steps before probing it again keeps within the budget.
std::int64_t TeamGovernor::wait_after(double r) {
  const double wait = std::ceil(double(kProbeSteps) * std::max(r - 1, 0.0) / kBudget);
  return std::clamp<std::int64_t>(std::int64_t(std::min(wait, double(kMaxInterval))), kWindow, kMaxInterval);
}

void TeamGovernor::finish_probe() {
  probing_ = false;
  const double probe = std::accumulate(probe_.begin(), probe_.end(), 0.0) / double(probe_.size());
  const double current = current_mean();
  if (probe < current * (1 - kMargin)) {
    // The team left behind is the one a next probe is likeliest to go back to: wait as for its ratio.
    rung_ = probe_rung_, ++moves_;
    recent_ = probe_, next_ = recent_.size() % kWindow;
    until_probe_ = wait_after(current / probe);
    return;
  }
  until_probe_ = wait_after(current > 0 ? probe / current : 1.0);
}

}  // namespace dpdrng::dpd
