#include "dpdrng/study/runner.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <ostream>
#include <thread>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace dpdrng::study {

std::string format_duration(double s) {
  char buf[32];
  if (s < 60)
    std::snprintf(buf, sizeof buf, "%.0fs", s);
  else if (s < 3600)
    std::snprintf(buf, sizeof buf, "%dm%02ds", int(s) / 60, int(s) % 60);
  else
    std::snprintf(buf, sizeof buf, "%dh%02dm", int(s) / 3600, (int(s) % 3600) / 60);
  return buf;
}

namespace {

// A cell allocates its taps afresh (a default-study cell 50–100 MB of raw words, in pieces of a few hundred KB,
// and buffers beside them) and frees them at its end. glibc hands such pages back to the kernel (pieces above its
// mmap threshold are unmapped, the heap's free top is trimmed), and the next cell then takes a page fault, and a
// page cleared, for every 4 KB again. Keeping freed memory in the process for the next cell changes no result.
void keep_freed_memory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's largest: pieces under 32 MB come from the heap
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

}  // namespace

RunSummary run_study(const StudyConfig& config, Store& store, const RunOptions& options, const MeasureFn& measure) {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  keep_freed_memory();
  const std::vector<Cell> cells = select_shard(enumerate_cells(config), options.shard);
  RunSummary sum;
  sum.cells = cells.size();

  std::vector<Cell> todo;
  for (const auto& c : cells) {
    std::string why;
    switch (store.state(c, &why)) {
      case Store::State::stored: ++sum.resumed; break;
      case Store::State::missing: todo.push_back(c); break;
      case Store::State::unreadable:
        sum.unreadable.push_back(store.cell_path(c).string());
        if (options.progress)
          *options.progress << "[study] warning: " << store.cell_path(c).string() << " is unreadable (" << why
                            << "): computing the cell again\n";
        todo.push_back(c);
        break;
    }
  }
  // Cells that also run the NIST battery cost many times a plain cell: they go last, so that an interrupted or
  // deadline-bound run has whole replica sets of physics and pass fractions first. The order of execution
  // does not change any result (each cell is independent), and shards still select by the canonical order.
  std::stable_partition(todo.begin(), todo.end(), [](const Cell& c) { return !c.nist; });
  if (options.progress && sum.resumed > 0)
    *options.progress << "[study] " << sum.resumed << " of " << sum.cells << " cells already stored: resuming\n";

  // More workers than cells would only idle; a lone cell gets the whole thread budget for its own loops.
  const int workers = std::max(1, std::min<int>(options.threads, static_cast<int>(todo.size())));
  const int inner_threads = std::max(1, options.threads / workers);
  std::atomic<std::size_t> next{0};
  std::mutex mu;  // guards sum and the progress stream
  // NIST cells cost many times a plain cell: the ETA averages the two kinds apart.
  double busy[2] = {0, 0};
  std::size_t done_kind[2] = {0, 0}, left_kind[2] = {0, 0};
  for (const auto& c : todo) ++left_kind[c.nist];
  std::exception_ptr store_error;

  auto worker = [&] {
    for (;;) {
      const std::size_t k = next.fetch_add(1);
      if (k >= todo.size()) return;
      const Cell& cell = todo[k];
      const auto c0 = clock::now();
      CellResult r;
      try {
        r = measure(cell, config, inner_threads);
      } catch (const std::exception& e) {
        // One broken cell must not stop the sweep: it is stored as failed, with the reason.
        r = CellResult{};
        r.status = CellStatus::failed;
        r.reason = e.what();
      }
      r.cell = cell;
      r.seconds = std::chrono::duration<double>(clock::now() - c0).count();
      try {
        store.save(r);
      } catch (...) {
        std::lock_guard lk(mu);
        if (!store_error) store_error = std::current_exception();
        next = todo.size();  // a store that cannot be written is fatal: stop handing out cells
        return;
      }
      std::lock_guard lk(mu);
      ++sum.computed;
      if (r.status == CellStatus::unstable) ++sum.unstable;
      if (r.status == CellStatus::disrupted) ++sum.disrupted;
      if (r.status == CellStatus::failed) ++sum.failed;
      busy[cell.nist] += r.seconds;
      ++done_kind[cell.nist];
      --left_kind[cell.nist];
      if (options.progress) {
        const std::size_t done = sum.resumed + sum.computed;
        double eta = 0;
        for (int k = 0; k < 2; ++k) {
          const int other = 1 - k;
          const double avg = done_kind[k] ? busy[k] / double(done_kind[k])
                                          : (done_kind[other] ? busy[other] / double(done_kind[other]) : 0.0);
          eta += avg * double(left_kind[k]) / workers;
        }
        char line[256];
        std::snprintf(line, sizeof line, "[study] %zu/%zu cells  %-10s %-7s %-9s rep%-2d %6.1fs  %s%s  ETA %s\n",
                      done, sum.cells, cell.label().c_str(), std::string(rng::to_string(cell.distribution)).c_str(),
                      cell.seeding_name().c_str(),
                      cell.replica, r.seconds, std::string(to_string(r.status)).c_str(),
                      r.status == CellStatus::ok ? "" : (" (" + r.reason + ")").c_str(), format_duration(eta).c_str());
        *options.progress << line << std::flush;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (store_error) std::rethrow_exception(store_error);
  sum.seconds = std::chrono::duration<double>(clock::now() - t0).count();
  return sum;
}

}  // namespace dpdrng::study
