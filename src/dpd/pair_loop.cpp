// The pair loop around a noise kernel (pair_loop.hpp): scheduling, sorting, gather and scatter, forces and
// reductions, compiled once for every noise.
#include "dpdrng/dpd/pair_loop.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

#include "dpdrng/dpd/neighbours.hpp"
#include "dpdrng/dpd/spin.hpp"
#include "dpdrng/dpd/pair_filter.hpp"

namespace dpdrng::dpd {

namespace {

// Appends the k pairs (first(t), second(t)) to out, each under its canonical key (i < j), with its used words
// (`words` a pair, from used) and ζ.
template <class First, class Second>
void append_in_range(InRangeTap& out, First first, Second second, std::size_t k, const std::uint64_t* used,
                     int words, const double* zeta) {
  for (std::size_t t = 0; t < k; ++t) {
    const std::uint64_t a = first(t), b = second(t);
    out.keys.push_back(a < b ? a << 32 | b : b << 32 | a);
  }
  out.words.insert(out.words.end(), used, used + k * std::size_t(words));
  out.zeta.insert(out.zeta.end(), zeta, zeta + k);
}

// Puts the pairs of `tap` into ascending key order, their words and ζ with them.
void sort_by_key(InRangeTap& tap) {
  if (std::is_sorted(tap.keys.begin(), tap.keys.end())) return;
  const std::size_t n = tap.size(), w = std::size_t(tap.words_per_pair);
  std::vector<std::size_t> order(n);
  for (std::size_t t = 0; t < n; ++t) order[t] = t;
  std::sort(order.begin(), order.end(), [&tap](std::size_t a, std::size_t b) { return tap.keys[a] < tap.keys[b]; });
  InRangeTap sorted;
  sorted.keys.reserve(n), sorted.words.reserve(n * w), sorted.zeta.reserve(n);
  for (const std::size_t t : order) {
    sorted.keys.push_back(tap.keys[t]);
    sorted.words.insert(sorted.words.end(), tap.words.begin() + std::ptrdiff_t(t * w),
                        tap.words.begin() + std::ptrdiff_t((t + 1) * w));
    sorted.zeta.push_back(tap.zeta[t]);
  }
  tap.keys.swap(sorted.keys), tap.words.swap(sorted.words), tap.zeta.swap(sorted.zeta);
}

}  // namespace

// Copies between the System's order and the sorted order; restrict lets each pass vectorise (gathers, scatters).
namespace permuted {

template <class T>
void gather(const std::uint32_t* __restrict order, std::uint32_t lo, std::uint32_t hi, const T* __restrict from,
            T* __restrict to) {
  for (std::uint32_t k = lo; k < hi; ++k) to[k] = from[order[k]];
}

template <class T>
void scatter(const std::uint32_t* __restrict order, std::uint32_t lo, std::uint32_t hi, const T* __restrict from,
             T* __restrict to) {
  for (std::uint32_t k = lo; k < hi; ++k) to[order[k]] = from[k];
}

}  // namespace permuted

namespace {

// What the cells loop's second pass adds up for each pair inside r_c: the force on the own bead s·d, the
// conservative weight and w (DpdKernel::evaluate's and conservative_weight's values).
struct PairTerms {
  double *gx, *gy, *gz, *cw, *w;
};

// The first pass over pairs [first, last) of a layer: every pair's terms, in a loop that carries no sum, so that
// it vectorises (gathers of the partners' velocities included); the second pass sums them in the pair order of
// the scalar loop, which keeps every total's bits. Own bead own[t] and partner j[t] are sorted indices; a is
// a_ij for every pair (one bead type).
template <bool Zero>
void pair_terms(const double* __restrict dx, const double* __restrict dy, const double* __restrict dz,
                const double* __restrict r2, const double* __restrict zeta, const std::uint32_t* __restrict own,
                const std::uint32_t* __restrict j, const double* __restrict vx, const double* __restrict vy,
                const double* __restrict vz, double a, const DpdKernel& k, std::size_t first, std::size_t last,
                double* __restrict gx, double* __restrict gy, double* __restrict gz, double* __restrict cw,
                double* __restrict w) {
  const double rc = k.rc, gamma = k.gamma, sig = k.sigma * k.inv_sqrt_dt;
  for (std::size_t t = first; t < last; ++t) {
    const std::uint32_t p = own[t], q = j[t];
    const double z = Zero ? 0.0 : zeta[t];
    const PairForce pf = DpdKernel::evaluate(r2[t], dx[t], dy[t], dz[t], vx[q] - vx[p], vy[q] - vy[p],
                                             vz[q] - vz[p], a, z, rc, gamma, sig);
    gx[t] = pf.s * dx[t], gy[t] = pf.s * dy[t], gz[t] = pf.s * dz[t];
    cw[t] = DpdKernel::conservative_weight(pf, r2[t]);
    w[t] = pf.w;
  }
}

class PairLoop final : public PairForces {
 public:
  PairLoop(std::unique_ptr<NoiseKernel> noise, const DpdKernel& kernel, PairMode mode, int threads, std::size_t n,
           std::vector<std::pair<std::uint32_t, std::uint32_t>> tap_pairs, std::size_t series_steps)
      : noise_(std::move(noise)), zero_(noise_->zero()), words_(noise_->words()), k_(kernel), mode_(mode),
        threads_(threads > 0 ? threads : omp_get_max_threads()), tap_pairs_(std::move(tap_pairs)),
        series_steps_(series_steps) {
    series_ordered_ = std::all_of(tap_pairs_.begin(), tap_pairs_.end(), [](const auto& p) { return p.first < p.second; });
    scratch_.resize(threads_);
    noise_->threads(threads_);
    if (mode_ == PairMode::all) {
      rows_.resize(n);
      fcx_.resize(n), fcy_.resize(n), fcz_.resize(n);
      for (auto& sc : scratch_) sc.resize(n);
    }
  }

  int words_per_pair() const override { return words_; }
  std::uint64_t list_builds() const override { return cells_.builds(); }

  ForceSums compute(System& s, VelocityView v, std::uint64_t step, bool tap_raw, bool tap_series, bool tap_zeta,
                    Taps& taps) override {
    const std::size_t n = s.size();
    RawTap* tap = nullptr;
    if (tap_raw && !zero_) {
      tap = &taps.raw.emplace_back();
      // A tap's storage given back (Taps::recycled) serves again, rather than fresh pages every tapped step.
      if (!taps.recycled.empty()) *tap = std::move(taps.recycled.back()), taps.recycled.pop_back();
      tap->step = static_cast<std::int64_t>(step);
      tap->words_per_pair = words_;
    }
    const Ctx c{s, v, step, tap, tap_zeta && !zero_, configurational_, tap_in_range_ && !zero_};
    // Generator calls per pair: the blocks feed hashes a second block.
    const std::uint64_t calls = zero_ ? 0 : noise_->feed() == rng::Feed::blocks ? 2 : 1;
    ForceSums sums;
    if (mode_ == PairMode::all) {
      const std::size_t slots = n * (n - 1) / 2;
      if (noise_->stream()) noise_->begin_step(slots);
      // Every slot is written (tap_rows): storage of the right length needs no clearing.
      if (tap)
        for (int w = 0; w < words_; ++w)
          if (tap->words[w].size() != slots) tap->words[w].assign(slots, 0);
      if (zero_)
        all_rows<true>(c);
      else
        all_rows<false>(c);
      sums = reduce(s, c.conf);
      sums.numbers = calls * slots;
      sums.candidates = slots;
    } else {
      sums = compute_cells(c);
      sums.numbers = calls * sums.in_range;
    }
    if (tap_series && !zero_) record_series(s, step, taps);
    if (c.in_tap) gather_in_range(taps.in_range, step);
    return sums;
  }

  void finish_taps(Taps& taps) override {
    if (!stage_.steps.empty()) flush_stage(taps);
  }

  double zeta_of(const System& s, std::uint32_t i, std::uint32_t j, std::uint64_t step) const override {
    if (zero_ || (noise_->stream() && mode_ != PairMode::all)) return std::nan("");
    std::uint64_t words[2] = {0, 0};
    double zeta = 0;
    noise_->pair(pair_input(s, i, j, step), pair_slot(i, j, s.size()), words, zeta);
    return zeta;
  }

  // ζ in one batch through the noise kernel (the blocks NoiseKernel::pair gives, pair by pair): a hash's, or the
  // stream's from its pairs' slots of this step (all mode, where every pair has one).
  void zetas_of(const System& s, const std::uint32_t* i, const std::uint32_t* j, std::size_t n, std::uint64_t step,
                double* out) const override {
    if (!batches()) return PairForces::zetas_of(s, i, j, n, step, out);
    batch_of(s, i, j, n, step, out, {nullptr, nullptr});
  }

  double ns_per_number() const override { return noise_->ns_per_number(); }
  double ns_per_zeta() const override { return noise_->ns_per_zeta(); }

 private:
  struct Rec {
    std::uint32_t j;
    double fx, fy, fz;
  };
  struct Row {
    std::vector<Rec> rec;
    std::vector<std::array<double, 3>> conf;  // the reactions' conservative parts, on configurational steps
    std::uint32_t count = 0;
    double w[3] = {0, 0, 0}, wc[3] = {0, 0, 0};
    double min_r2 = 0;
    double laplacian = 0;  // Σ over the row's pairs of ∇²u
    ZetaSums zeta;
    InRangeTap in_range;   // on steps that tap the pairs inside r_c
  };
  struct Scratch {
    // A row's pairs (all mode) or a layer's (cells mode): partners (sorted indices in cells mode); cells:
    // the pairs' bead ids, own (pi) and partner's (ids), and each own bead's number of pairs, in order.
    std::vector<double> dx, dy, dz, r2;
    std::vector<std::uint32_t> j, ids, pi, counts;
    std::vector<std::uint32_t> own;  // cells: the pairs' own beads' sorted indices
    std::vector<std::size_t> slots;  // all pairs under the stream: the pairs' slots
    std::vector<double> zeta;
    std::vector<double> gx, gy, gz, cw, w;  // cells: the pairs' terms (pair_terms)
    std::vector<std::uint64_t> tap[2];  // cells: a layer's tapped words
    std::vector<std::uint64_t> used;    // the batch's used words, on steps that tap the pairs inside r_c
    void resize(std::size_t n) { grow_pairs(n + pair_filter::kSlack); }
    // Room for n pairs, keeping those already collected (callers add the filter's slack).
    void grow_pairs(std::size_t n) {
      if (dx.size() >= n) return;
      n = std::max(n, 2 * dx.size());
      dx.resize(n), dy.resize(n), dz.resize(n), r2.resize(n), j.resize(n), ids.resize(n), pi.resize(n);
      zeta.resize(n), own.resize(n), slots.resize(n);
      gx.resize(n), gy.resize(n), gz.resize(n), cw.resize(n), w.resize(n);
    }
    pair_filter::Out out() { return {dx.data(), dy.data(), dz.data(), r2.data(), j.data()}; }
    // A list of candidates and room past it for whole-vector copies and loads: cells, the candidates of the
    // cell at hand (list_candidates), `listed` of them; all pairs, a row's candidates the prefilter passed.
    std::vector<double> lx, ly, lz;
    std::vector<std::uint32_t> lid;
    std::uint32_t listed = 0;
    void grow_list(std::size_t n) {
      if (lx.size() >= n) return;
      n = std::max(n, 2 * lx.size());
      lx.resize(n), ly.resize(n), lz.resize(n), lid.resize(n);
    }
    pair_filter::Listed list() const { return {lx.data(), ly.data(), lz.data(), lid.data()}; }
    pair_filter::ListRoom list_room() { return {lx.data(), ly.data(), lz.data(), lid.data()}; }
  };
  struct CellSums {
    double w[3] = {0, 0, 0}, wc[3] = {0, 0, 0};
    double min_r2 = 0;
    double laplacian = 0;
    std::uint64_t count = 0, candidates = 0;
    ZetaSums zeta;
  };
  struct Ctx {
    System& s;
    VelocityView v;
    std::uint64_t step;
    RawTap* tap;
    bool tap_zeta;
    bool conf;    // sum the configurational temperature's parts this step
    bool in_tap;  // record the pairs inside r_c (Taps::in_range)
  };

  // Rows in groups of kGroup, a group's noise drawn in one batch (row_group).
  static constexpr std::size_t kGroup = 16;

  template <bool Zero>
  void all_rows(const Ctx& c) {
    const std::size_t n = c.s.size(), groups = (n + kGroup - 1) / kGroup;
    round_positions(c.s);
#pragma omp parallel for num_threads(team_size(threads_)) schedule(dynamic, 1)
    for (std::size_t g = 0; g < groups; ++g) {
      const auto i0 = static_cast<std::uint32_t>(g * kGroup);
      const auto i1 = static_cast<std::uint32_t>(std::min(n, (g + 1) * kGroup));
      row_group<Zero>(c, i0, i1, omp_get_thread_num());
      if (c.tap) tap_rows(c, i0, i1, omp_get_thread_num());
    }
  }

  // The positions for the rows' prefilter: on the 16-bit grid where it serves (pair_filter::grid_serves),
  // rounded to float otherwise (pair_filter::append_rounded), with the threshold of each.
  void round_positions(const System& s) {
    const std::size_t n = s.size();
    double extent = std::max({s.box.L[0], s.box.L[1], s.box.L[2]});
    for (const auto* a : {&s.x, &s.y, &s.z})
      for (std::size_t i = 0; i < n; ++i) extent = std::max(extent, std::abs((*a)[i]));
    grid_ = pair_filter::grid_serves(s.box, k_.rc, extent);
    if (grid_) {
      for (std::size_t a = 0; a < 3; ++a) {
        const double scale = 65536.0 / s.box.L[a];
        const std::vector<double>& p = a == 0 ? s.x : a == 1 ? s.y : s.z;
        std::vector<std::uint16_t>& q = grid_pos_[a];
        q.resize(n + pair_filter::kSlackG);
        for (std::size_t i = 0; i < n; ++i) q[i] = pair_filter::to_grid(p[i], scale);
      }
      threshold_g_ = pair_filter::grid_threshold(k_.rc, 65536.0 / std::min({s.box.L[0], s.box.L[1], s.box.L[2]}));
      return;
    }
    for (auto* a : {&xf_, &yf_, &zf_}) a->resize(n + pair_filter::kSlackF);
    for (std::size_t i = 0; i < n; ++i)
      xf_[i] = static_cast<float>(s.x[i]), yf_[i] = static_cast<float>(s.y[i]), zf_[i] = static_cast<float>(s.z[i]);
    threshold_f_ = pair_filter::rounded_threshold(k_.rc2(), extent);
  }

  // Row i's centre and box for the prefilter.
  pair_filter::Rounded rounded(const Box& box, std::uint32_t i) const {
    const auto Lx = static_cast<float>(box.L[0]), Ly = static_cast<float>(box.L[1]), Lz = static_cast<float>(box.L[2]);
    return {xf_.data(), yf_.data(), zf_.data(), xf_[i], yf_[i], zf_[i], Lx, Ly, Lz, threshold_f_};
  }
  pair_filter::Grid16 on_grid(std::uint32_t i) const {
    const auto& [x, y, z] = grid_pos_;
    return {x.data(), y.data(), z.data(), x[i], y[i], z[i], threshold_g_};
  }

  // Row i's candidates after it, [i + 1, n), through the step's prefilter and the exact test, appended to sc
  // from `off` on; returns the new count.
  std::size_t append_row(const System& s, std::uint32_t i, const pair_filter::Centre& ctr, Scratch& sc,
                         std::size_t off) const {
    const auto n = std::uint32_t(s.size());
    if (grid_)
      return pair_filter::append_grid(s.x.data(), s.y.data(), s.z.data(), on_grid(i), i + 1, n, ctr, sc.list_room(),
                                       sc.out(), off);
    return pair_filter::append_rounded(s.x.data(), s.y.data(), s.z.data(), rounded(s.box, i), i + 1, n, ctr,
                                       sc.list_room(), sc.out(), off);
  }

  // Rows [i0, i1), on every step: each row's pairs inside r_c collected one row after another, their ζ in one
  // batch (a row holds ~6 such pairs in the paper's fluid: too few for the vectorised hash and Box–Muller), then
  // each row's forces. A hash's block is a function of the pair alone and the stream's is its slot's (passed per
  // pair), so the grouping changes no number.
  // Zero (the ζ = 0 baseline): the same path without the noise, so that the two differ by the noise alone.
  template <bool Zero>
  void row_group(const Ctx& c, std::uint32_t i0, std::uint32_t i1, int thread) {
    Scratch& sc = scratch_[std::size_t(thread)];
    const System& s = c.s;
    const std::size_t n = s.size();
    const double rc2 = k_.rc2();
    const bool stream = !Zero && noise_->stream();
    sc.counts.clear();
    std::size_t off = 0;
    for (std::uint32_t i = i0; i < i1; ++i) {
      const std::size_t m = n - i - 1;
      sc.grow_pairs(off + m + pair_filter::kSlack);
      sc.grow_list(m + pair_filter::kSlackF);
      const pair_filter::Centre ctr = pair_filter::centre(s.box, s.x[i], s.y[i], s.z[i], rc2);
      const std::size_t k = append_row(s, i, ctr, sc, off) - off;
      std::fill_n(sc.pi.data() + off, k, i);
      if (stream) row_slots(i, n, sc.j.data() + off, k, sc.slots.data() + off);
      sc.counts.push_back(std::uint32_t(k));
      off += k;
    }
    if constexpr (!Zero) {
      const PairBatch b{sc.pi.data(), sc.j.data(), off, sc.dx.data(), sc.dy.data(), sc.dz.data(), c.step, 0,
                        {nullptr, nullptr}, sc.zeta.data(), c.in_tap ? used_room(sc, off) : nullptr,
                        stream ? sc.slots.data() : nullptr};
      noise_->pairs(b, thread);
    }
    // One bead type and no configurational sums: the group's pair terms in one vectorised pass, then each
    // row's sums over them (row_sums), as in cells mode.
    const bool terms = !c.conf && k_.ntypes == 1;
    if (terms)
      pair_terms<Zero>(sc.dx.data(), sc.dy.data(), sc.dz.data(), sc.r2.data(), sc.zeta.data(), sc.pi.data(),
                        sc.j.data(), c.v.vx, c.v.vy, c.v.vz, k_.a[0], k_, 0, off, sc.gx.data(), sc.gy.data(),
                        sc.gz.data(), sc.cw.data(), sc.w.data());
    off = 0;
    for (std::uint32_t i = i0; i < i1; ++i) {
      const std::size_t k = sc.counts[i - i0];
      if (c.in_tap) record_row(i, k, sc, off);
      if (terms && c.tap_zeta)
        row_sums<true>(c, i, k, sc, off, rows_[i]);
      else if (terms)
        row_sums<false>(c, i, k, sc, off, rows_[i]);
      else
        forces<Zero>(c, i, k, sc, off, rows_[i]);
      off += k;
    }
  }

  // Row i's forces from the terms pair_terms left in sc for its m pairs from `off` on (one bead type, no
  // configurational sums): forces<false, false>'s sums over the same values in the same order, so the same bits.
  // TapZeta (Ctx::tap_zeta, never with the ζ = 0 baseline): the ζ moments too.
  template <bool TapZeta>
  void row_sums(const Ctx& c, std::uint32_t i, std::size_t m, const Scratch& sc, std::size_t off, Row& row) {
    double fx = 0, fy = 0, fz = 0, w0 = 0, w1 = 0, w2 = 0, c0 = 0, c1 = 0, c2 = 0, ww = 0, wwzz = 0;
    double min_r2 = k_.rc2();
    if (row.rec.size() < m) row.rec.resize(m);
    row.zeta = ZetaSums{};
    if constexpr (TapZeta) row.zeta.add(sc.zeta.data() + off, m);
    for (std::size_t p = off; p < off + m; ++p) {
      const double dx = sc.dx[p], dy = sc.dy[p], dz = sc.dz[p], r2 = sc.r2[p];
      const double gx = sc.gx[p], gy = sc.gy[p], gz = sc.gz[p], cw = sc.cw[p];
      fx += gx, fy += gy, fz += gz;
      w0 -= gx * dx, w1 -= gy * dy, w2 -= gz * dz;
      c0 += cw * dx * dx, c1 += cw * dy * dy, c2 += cw * dz * dz;
      row.rec[p - off] = {sc.j[p], gx, gy, gz};
      if constexpr (TapZeta) {
        const double w2p = sc.w[p] * sc.w[p], zeta = sc.zeta[p];
        ww += w2p, wwzz += w2p * zeta * zeta;
      }
      min_r2 = std::min(min_r2, r2);
    }
    c.s.fx[i] = fx, c.s.fy[i] = fy, c.s.fz[i] = fz;
    fcx_[i] = 0, fcy_[i] = 0, fcz_[i] = 0;
    row.laplacian = 0;
    if constexpr (TapZeta) row.zeta.w2 = ww, row.zeta.w2z2 = wwzz;
    row.count = static_cast<std::uint32_t>(m);
    row.w[0] = w0, row.w[1] = w1, row.w[2] = w2;
    row.wc[0] = c0, row.wc[1] = c1, row.wc[2] = c2;
    row.min_r2 = min_r2;
  }

  // Pass 2: forces for the m in-range pairs held in sc from pair `off` on (partners sc.j, ζ in sc.zeta unless
  // Zero). The configurational sums cost a scatter per pair, so only the steps that sample them pay for them.
  template <bool Zero>
  void forces(const Ctx& c, std::uint32_t i, std::size_t m, const Scratch& sc, std::size_t off, Row& row) {
    if (c.conf)
      forces<Zero, true>(c, i, m, sc, off, row);
    else
      forces<Zero, false>(c, i, m, sc, off, row);
  }
  template <bool Zero, bool Conf>
  void forces(const Ctx& c, std::uint32_t i, std::size_t m, const Scratch& sc, std::size_t off, Row& row) {
    const System& s = c.s;
    const double vxi = c.v.vx[i], vyi = c.v.vy[i], vzi = c.v.vz[i];
    const double* arow = &k_.a[std::size_t(s.type[i]) * k_.ntypes];
    const double rc = k_.rc, gamma = k_.gamma, sig = k_.sigma * k_.inv_sqrt_dt, inv_rc = 1.0 / k_.rc;
    double fx = 0, fy = 0, fz = 0, w0 = 0, w1 = 0, w2 = 0, c0 = 0, c1 = 0, c2 = 0;
    double cfx = 0, cfy = 0, cfz = 0, lap = 0, ww = 0, wwzz = 0;
    double min_r2 = k_.rc2();
    if (row.rec.size() < m) row.rec.resize(m);
    if (Conf && row.conf.size() < m) row.conf.resize(m);
    row.zeta = ZetaSums{};
    if (c.tap_zeta) row.zeta.add(sc.zeta.data() + off, m);
    for (std::size_t t = 0; t < m; ++t) {
      const std::size_t p = off + t;
      const std::uint32_t j = sc.j[p];
      const double dx = sc.dx[p], dy = sc.dy[p], dz = sc.dz[p], r2 = sc.r2[p];
      // The ζ = 0 baseline keeps the constant, as the benchmark's floor must.
      const double zeta = Zero ? 0.0 : sc.zeta[p];
      const double a = arow[s.type[j]];
      const PairForce pf = DpdKernel::evaluate(r2, dx, dy, dz, c.v.vx[j] - vxi, c.v.vy[j] - vyi, c.v.vz[j] - vzi,
                                               a, zeta, rc, gamma, sig);
      const double gx = pf.s * dx, gy = pf.s * dy, gz = pf.s * dz;
      fx += gx, fy += gy, fz += gz;
      // r_ij = −d and F_ij = s·d: (r_ij)_α (F_ij)_α = −s d_α²; conservative: a w d_α² / r, F^C_i = −(a w / r) d.
      w0 -= gx * dx, w1 -= gy * dy, w2 -= gz * dz;
      const double cw = DpdKernel::conservative_weight(pf, r2);
      c0 += cw * dx * dx, c1 += cw * dy * dy, c2 += cw * dz * dz;
      row.rec[t] = {j, gx, gy, gz};
      if constexpr (Conf) {
        const double hx = -cw * dx, hy = -cw * dy, hz = -cw * dz;
        cfx += hx, cfy += hy, cfz += hz;
        row.conf[t] = {hx, hy, hz};
        lap += DpdKernel::conservative_laplacian(pf, r2, a, inv_rc);
      }
      const double w2p = pf.w * pf.w;
      ww += w2p, wwzz += w2p * zeta * zeta;
      min_r2 = std::min(min_r2, r2);
    }
    c.s.fx[i] = fx, c.s.fy[i] = fy, c.s.fz[i] = fz;
    fcx_[i] = cfx, fcy_[i] = cfy, fcz_[i] = cfz;
    row.laplacian = lap;
    if (c.tap_zeta) row.zeta.w2 = ww, row.zeta.w2z2 = wwzz;
    row.count = static_cast<std::uint32_t>(m);
    row.w[0] = w0, row.w[1] = w1, row.w[2] = w2;
    row.wc[0] = c0, row.wc[1] = c1, row.wc[2] = c2;
    row.min_r2 = min_r2;
  }

  // The slots of row i's k partners j (pair_slot), restrict so that the loop vectorises.
  static void row_slots(std::uint32_t i, std::size_t n, const std::uint32_t* __restrict j, std::size_t k,
                        std::size_t* __restrict out) {
    const std::size_t before = pair_slot(i, i + 1, n) - i - 1;
    for (std::size_t t = 0; t < k; ++t) out[t] = before + j[t];
  }

  // Rows [i0, i1) on a step that taps every pair's words (never the ζ = 0 baseline), once row_group has done
  // their forces: each row's geometry of all its pairs, whose words the kernel writes at their slots.
  void tap_rows(const Ctx& c, std::uint32_t i0, std::uint32_t i1, int thread) {
    Scratch& sc = scratch_[std::size_t(thread)];
    const System& s = c.s;
    const std::size_t n = s.size();
    for (std::uint32_t i = i0; i < i1; ++i) {
      const std::size_t m = n - i - 1, base = pair_slot(i, i + 1, n);
      sc.grow_pairs(m);
      geometry(s.x.data() + i + 1, s.y.data() + i + 1, s.z.data() + i + 1, s.x[i], s.y[i], s.z[i], s.box, m,
               sc.dx.data(), sc.dy.data(), sc.dz.data(), sc.r2.data());
      RowWords b{i, m, sc.dx.data(), sc.dy.data(), sc.dz.data(), c.step, base, {nullptr, nullptr}};
      for (int w = 0; w < words_; ++w) b.tap[w] = c.tap->words[std::size_t(w)].data() + base;
      noise_->row_words(b, thread);
    }
  }

  // Room for the used words of k pairs in sc.
  std::uint64_t* used_room(Scratch& sc, std::size_t k) const {
    const std::size_t need = k * std::size_t(noise_->used_words());
    if (sc.used.size() < need) sc.used.resize(std::max(need, 2 * sc.used.size()));
    return sc.used.data();
  }

  // All mode: row i's k pairs inside r_c, held in sc from pair `off` on, as its part of the step's tap.
  void record_row(std::uint32_t i, std::size_t k, const Scratch& sc, std::size_t off) {
    InRangeTap& out = rows_[i].in_range;
    out.clear();
    const std::uint32_t* js = sc.j.data() + off;
    const int w = noise_->used_words();
    append_in_range(out, [i](std::size_t) { return i; }, [js](std::size_t t) { return js[t]; }, k,
                    sc.used.data() + off * std::size_t(w), w, sc.zeta.data() + off);
  }

  // The step's tap from the rows' or the cells' parts, in key order.
  void gather_in_range(InRangeTap& out, std::uint64_t step) {
    out.clear();
    out.step = static_cast<std::int64_t>(step);
    out.words_per_pair = noise_->used_words();
    auto add = [&out](const InRangeTap& part) {
      out.keys.insert(out.keys.end(), part.keys.begin(), part.keys.end());
      out.words.insert(out.words.end(), part.words.begin(), part.words.end());
      out.zeta.insert(out.zeta.end(), part.zeta.begin(), part.zeta.end());
    };
    if (mode_ == PairMode::all)
      for (const Row& row : rows_) add(row.in_range);
    else
      for (const InRangeTap& part : cell_in_range_) add(part);
    sort_by_key(out);
  }

  // The positions keep the filter's slack past the last bead (list_candidates copies whole vectors).
  void resize_sorted(std::size_t n) {
    for (auto* a : {&xs_, &ys_, &zs_}) a->resize(n + pair_filter::kSlack);
    for (auto* a : {&vxs_, &vys_, &vzs_, &fxs_, &fys_, &fzs_, &fcx_, &fcy_, &fcz_}) a->resize(n);
    types_.resize(n);
  }

  // Sorted copies of what the pairs read (positions, the dissipative force's velocities, types),
  // and zeroed sorted forces, by the team of the sort: each thread copies the beads of the layers it will own
  // (own_layers), so they start in its cache. Each sorted slot is written once. One array at a time: a pass
  // reads one System array at random and writes one sorted array in sequence, which both stay in L2 at
  // 24 000 beads, where the seven arrays read at once (and the ten written) do not.
  void gather(const System& s, VelocityView v, bool conf) {
    const auto [z0, z1] = own_layers(omp_get_thread_num(), omp_get_num_threads());
    const int per_layer = cells_.layer_cells();
    const std::uint32_t* order = cells_.order().data();
    const std::uint32_t lo = cells_.begin(z0 * per_layer), hi = cells_.begin(z1 * per_layer);
    permuted::gather(order, lo, hi, s.x.data(), xs_.data());
    permuted::gather(order, lo, hi, s.y.data(), ys_.data());
    permuted::gather(order, lo, hi, s.z.data(), zs_.data());
    permuted::gather(order, lo, hi, v.vx, vxs_.data());
    permuted::gather(order, lo, hi, v.vy, vys_.data());
    permuted::gather(order, lo, hi, v.vz, vzs_.data());
    permuted::gather(order, lo, hi, s.type.data(), types_.data());
    for (double* f : {fxs_.data(), fys_.data(), fzs_.data()}) std::fill(f + lo, f + hi, 0.0);
    if (conf)
      for (double* f : {fcx_.data(), fcy_.data(), fcz_.data()}) std::fill(f + lo, f + hi, 0.0);
  }

  // Thread t of nt owns a contiguous block of layers: its layers' writes to the next layer then stay on the
  // same core, except at the block's end.
  std::pair<int, int> own_layers(int t, int nt) const {
    const int layers = cells_.layers();
    return {layers * t / nt, layers * (t + 1) / nt};
  }

  // Cell c's candidates: its own beads and its forward neighbours'.
  std::size_t candidates(int c) const {
    const SortedCells::Run* runs = cells_.runs(c);
    std::size_t m = 0;
    for (int r = 0; r < cells_.run_count(c); ++r) m += cells_.end(runs[r].last) - cells_.begin(runs[r].first);
    return m;
  }

  // Cell c's candidates (its own beads, then its forward neighbours', run by run, in sorted order) copied into
  // sc's list. Each of the cell's beads then filters one list in whole vectors instead of each run's ragged
  // ends. The entries past the list's end hold positions or zeros (finite, and masked out by the filter).
  void list_candidates(int c, Scratch& sc) const {
    const std::size_t m = candidates(c);
    sc.grow_list(m + 2 * pair_filter::kSlack);
    const SortedCells::Run* runs = cells_.runs(c);
    std::size_t t = 0;
    for (int r = 0; r < cells_.run_count(c); ++r)
      t = pair_filter::list_range(xs_.data(), ys_.data(), zs_.data(), cells_.begin(runs[r].first),
                                  cells_.end(runs[r].last), sc.lx.data(), sc.ly.data(), sc.lz.data(), sc.lid.data(), t);
    sc.listed = std::uint32_t(t);
  }

  // Sorted bead a of cell c against the candidates after it in c's list (list_candidates: the rest of its cell,
  // then the forward neighbours'): the pairs inside r_c, appended to sc from pair `off` on (partners' sorted
  // indices in sc.j). Returns their number. sc must have room for the candidates and the filter's slack from
  // `off` on.
  std::size_t in_range(const Box& box, int c, std::uint32_t a, std::size_t off, Scratch& sc) const {
    const pair_filter::Centre ctr = pair_filter::centre(box, xs_[a], ys_[a], zs_[a], k_.rc2());
    const std::uint32_t lo = a - cells_.begin(c) + 1;
    const std::size_t kept = cells_.wraps(c)
                                 ? pair_filter::append_listed<true>(sc.list(), lo, sc.listed, ctr, sc.out(), off)
                                 : pair_filter::append_listed<false>(sc.list(), lo, sc.listed, ctr, sc.out(), off);
    return kept - off;
  }

  // Room in sc for every pair of cell c's beads from pair `off` on.
  void room_for_cell(int c, std::size_t off, Scratch& sc) const {
    sc.grow_pairs(off + std::size_t(cells_.end(c) - cells_.begin(c)) * candidates(c) + pair_filter::kSlack);
  }

  std::uint64_t count_cell(const Box& box, int c, Scratch& sc) const {
    room_for_cell(c, 0, sc);
    list_candidates(c, sc);
    std::uint64_t count = 0;
    for (std::uint32_t a = cells_.begin(c); a < cells_.end(c); ++a) count += in_range(box, c, a, 0, sc);
    return count;
  }

  // Every pair inside r_c of the cells [c0, c1), in cell, bead and partner order, into sc; each own bead's
  // count in sc.counts. Returns the total.
  template <bool Zero>
  std::size_t collect(const Box& box, int c0, int c1, Scratch& sc) const {
    const std::uint32_t* ids = cells_.order().data();
    sc.counts.clear();
    std::size_t off = 0;
    for (int c = c0; c < c1; ++c) {
      room_for_cell(c, off, sc);
      list_candidates(c, sc);
      for (std::uint32_t a = cells_.begin(c); a < cells_.end(c); ++a) {
        const std::size_t k = in_range(box, c, a, off, sc);
        std::fill_n(sc.own.data() + off, k, a);
        if constexpr (!Zero) bead_ids(ids, ids[a], sc.j.data() + off, k, sc.pi.data() + off, sc.ids.data() + off);
        sc.counts.push_back(std::uint32_t(k));
        off += k;
      }
    }
    return off;
  }

  // The bead ids of k pairs of own bead `own` and sorted partners j, through the sort's order; restrict lets the
  // loop vectorise.
  static void bead_ids(const std::uint32_t* __restrict order, std::uint32_t own, const std::uint32_t* __restrict j,
                       std::size_t k, std::uint32_t* __restrict pi, std::uint32_t* __restrict ids) {
    for (std::size_t t = 0; t < k; ++t) ids[t] = order[j[t]], pi[t] = own;
  }

  // ζ of the k pairs collected for the cells [c0, c1), in one batch; their words to each cell's tap.
  void draw(const Ctx& cx, int c0, int c1, std::size_t k, Scratch& sc, int thread, bool tap) {
    // The layer's cells are consecutive, so are their pairs' slots.
    const std::uint64_t slot = slot_base_.empty() ? 0 : slot_base_[c0];
    PairBatch b{sc.pi.data(), sc.ids.data(), k, sc.dx.data(), sc.dy.data(), sc.dz.data(), cx.step, slot,
                {nullptr, nullptr}, sc.zeta.data(), cx.in_tap ? used_room(sc, k) : nullptr};
    if (tap)
      for (int w = 0; w < words_; ++w) {
        if (sc.tap[w].size() < k) sc.tap[w].resize(k);
        b.tap[w] = sc.tap[w].data();
      }
    noise_->pairs(b, thread);
    if (cx.in_tap) record_cells(c0, c1, sc);
    if (!tap) return;
    std::size_t off = 0, bead = 0;
    for (int c = c0; c < c1; ++c) {
      std::size_t n = 0;
      for (std::uint32_t q = cells_.begin(c); q < cells_.end(c); ++q) n += sc.counts[bead++];
      for (int w = 0; w < words_; ++w) cell_tap_[c][w].assign(sc.tap[w].begin() + off, sc.tap[w].begin() + off + n);
      off += n;
    }
  }

  // Cells mode: the pairs of the cells [c0, c1), collected and drawn in sc, as those cells' parts of the tap.
  void record_cells(int c0, int c1, const Scratch& sc) {
    const int w = noise_->used_words();
    std::size_t off = 0, bead = 0;
    for (int c = c0; c < c1; ++c) {
      std::size_t n = 0;
      for (std::uint32_t q = cells_.begin(c); q < cells_.end(c); ++q) n += sc.counts[bead++];
      InRangeTap& out = cell_in_range_[std::size_t(c)];
      out.clear();
      const std::uint32_t *pi = sc.pi.data() + off, *ids = sc.ids.data() + off;
      append_in_range(out, [pi](std::size_t t) { return pi[t]; }, [ids](std::size_t t) { return ids[t]; }, n,
                      sc.used.data() + off * std::size_t(w), w, sc.zeta.data() + off);
      off += n;
    }
  }

  // All pairs of layer z's cells: collected, their noise drawn in one batch, then each cell's forces.
  template <bool Zero>
  void do_layer(const Ctx& cx, int z, int thread, bool tap) {
    Scratch& sc = scratch_[std::size_t(thread)];
    const int c0 = z * cells_.layer_cells(), c1 = c0 + cells_.layer_cells();
    const std::size_t k = collect<Zero>(cx.s.box, c0, c1, sc);
    if constexpr (!Zero) draw(cx, c0, c1, k, sc, thread, tap);
    std::size_t off = 0, bead = 0;
    if (cx.conf || k_.ntypes != 1) {
      for (int c = c0; c < c1; ++c) cell_forces<Zero>(cx, c, sc, off, bead);
      return;
    }
    pair_terms<Zero>(sc.dx.data(), sc.dy.data(), sc.dz.data(), sc.r2.data(), sc.zeta.data(), sc.own.data(),
                     sc.j.data(), vxs_.data(), vys_.data(), vzs_.data(), k_.a[0], k_, 0, k, sc.gx.data(), sc.gy.data(),
                     sc.gz.data(), sc.cw.data(), sc.w.data());
    for (int c = c0; c < c1; ++c)
      if (cx.tap_zeta)
        cell_sums<Zero, true>(c, sc, off, bead);
      else
        cell_sums<Zero, false>(c, sc, off, bead);
  }

  // Candidates cell c's beads visit: each its cell's beads after it and all of the forward neighbours'.
  std::uint64_t cell_candidates(int c) const {
    const std::uint64_t own = cells_.end(c) - cells_.begin(c);
    return own * candidates(c) - own * (own + 1) / 2;
  }

  // Cell c's forces from the terms pair_terms left in sc (one bead type, no configurational sums): cell_forces'
  // sums over the same values in the same order, so the same bits. Pairs from `off` and own beads from `bead` on
  // (both advanced past them). TapZeta (Ctx::tap_zeta): the ζ moments too; a run without them skips their loads
  // and products.
  template <bool Zero, bool TapZeta>
  void cell_sums(int c, const Scratch& sc, std::size_t& off, std::size_t& bead) {
    const double *dxs = sc.dx.data(), *dys = sc.dy.data(), *dzs = sc.dz.data(), *r2s = sc.r2.data();
    const double *gxs = sc.gx.data(), *gys = sc.gy.data(), *gzs = sc.gz.data(), *cws = sc.cw.data();
    const double *ws = sc.w.data(), *zetas = sc.zeta.data();
    const std::uint32_t* js = sc.j.data();
    double *fxs = fxs_.data(), *fys = fys_.data(), *fzs = fzs_.data();
    double ww = 0, wwzz = 0;
    CellSums cs;
    cs.min_r2 = k_.rc2();
    for (std::uint32_t a = cells_.begin(c); a < cells_.end(c); ++a) {
      const std::size_t first = off, k = sc.counts[bead++];
      off += k;
      if constexpr (!Zero && TapZeta) cs.zeta.add(zetas + first, k);
      double fx = 0, fy = 0, fz = 0;
      for (std::size_t t = first; t < off; ++t) {
        const std::uint32_t b = js[t];
        const double dx = dxs[t], dy = dys[t], dz = dzs[t], r2 = r2s[t];
        const double gx = gxs[t], gy = gys[t], gz = gzs[t], cw = cws[t];
        fx += gx, fy += gy, fz += gz;
        fxs[b] -= gx, fys[b] -= gy, fzs[b] -= gz;
        cs.w[0] -= gx * dx, cs.w[1] -= gy * dy, cs.w[2] -= gz * dz;
        cs.wc[0] += cw * dx * dx, cs.wc[1] += cw * dy * dy, cs.wc[2] += cw * dz * dz;
        if constexpr (TapZeta) {
          const double zeta = Zero ? 0.0 : zetas[t];
          const double w2p = ws[t] * ws[t];
          ww += w2p, wwzz += w2p * zeta * zeta;
        }
        cs.min_r2 = std::min(cs.min_r2, r2);
      }
      fxs[a] += fx, fys[a] += fy, fzs[a] += fz;
      cs.count += k;
    }
    if constexpr (TapZeta) cs.zeta.w2 = ww, cs.zeta.w2z2 = wwzz;
    cs.candidates = cell_candidates(c);
    cell_sums_[c] = cs;
  }

  // The forces of cell c's pairs, collected in sc from pair `off` and own bead `bead` on (both advanced past
  // them). Writes only to the beads of c and its forward neighbours.
  template <bool Zero>
  void cell_forces(const Ctx& cx, int c, const Scratch& sc, std::size_t& off, std::size_t& bead) {
    if (cx.conf)
      cell_forces<Zero, true>(cx, c, sc, off, bead);
    else
      cell_forces<Zero, false>(cx, c, sc, off, bead);
  }
  template <bool Zero, bool Conf>
  void cell_forces(const Ctx& cx, int c, const Scratch& sc, std::size_t& off, std::size_t& bead) {
    const double rc = k_.rc, gamma = k_.gamma, sig = k_.sigma * k_.inv_sqrt_dt, inv_rc = 1.0 / k_.rc;
    double ww = 0, wwzz = 0;
    CellSums cs;
    cs.min_r2 = k_.rc2();
    for (std::uint32_t a = cells_.begin(c); a < cells_.end(c); ++a) {
      const std::size_t first = off, k = sc.counts[bead++];
      off += k;
      if constexpr (!Zero)
        if (cx.tap_zeta) cs.zeta.add(sc.zeta.data() + first, k);
      const double vxa = vxs_[a], vya = vys_[a], vza = vzs_[a];
      const double* arow = &k_.a[std::size_t(types_[a]) * k_.ntypes];
      double fx = 0, fy = 0, fz = 0, cfx = 0, cfy = 0, cfz = 0;
      for (std::size_t t = first; t < off; ++t) {
        const std::uint32_t b = sc.j[t];
        const double dx = sc.dx[t], dy = sc.dy[t], dz = sc.dz[t], r2 = sc.r2[t];
        const double zeta = Zero ? 0.0 : sc.zeta[t];
        const double aab = arow[types_[b]];
        const PairForce pf = DpdKernel::evaluate(r2, dx, dy, dz, vxs_[b] - vxa, vys_[b] - vya, vzs_[b] - vza,
                                                 aab, zeta, rc, gamma, sig);
        const double gx = pf.s * dx, gy = pf.s * dy, gz = pf.s * dz;
        fx += gx, fy += gy, fz += gz;
        fxs_[b] -= gx, fys_[b] -= gy, fzs_[b] -= gz;
        // r_ab = −d and F_ab = s·d: (r_ab)_α (F_ab)_α = −s d_α²; conservative: a w d_α² / r, F^C_a = −(a w / r) d.
        cs.w[0] -= gx * dx, cs.w[1] -= gy * dy, cs.w[2] -= gz * dz;
        const double cw = DpdKernel::conservative_weight(pf, r2);
        cs.wc[0] += cw * dx * dx, cs.wc[1] += cw * dy * dy, cs.wc[2] += cw * dz * dz;
        if constexpr (Conf) {
          const double hx = -cw * dx, hy = -cw * dy, hz = -cw * dz;
          cfx += hx, cfy += hy, cfz += hz;
          fcx_[b] -= hx, fcy_[b] -= hy, fcz_[b] -= hz;
          cs.laplacian += DpdKernel::conservative_laplacian(pf, r2, aab, inv_rc);
        }
        const double w2p = pf.w * pf.w;
        ww += w2p, wwzz += w2p * zeta * zeta;
        cs.min_r2 = std::min(cs.min_r2, r2);
      }
      fxs_[a] += fx, fys_[a] += fy, fzs_[a] += fz;
      if constexpr (Conf) fcx_[a] += cfx, fcy_[a] += cfy, fcz_[a] += cfz;
      cs.count += k;
    }
    if (cx.tap_zeta) cs.zeta.w2 = ww, cs.zeta.w2z2 = wwzz;
    cs.candidates = cell_candidates(c);
    cell_sums_[c] = cs;
  }

  ForceSums compute_cells(const Ctx& cx) {
    System& s = cx.s;
    const bool team = s.size() >= SortedCells::kParallelBeads;
    cells_.prepare(s, k_.rc, team ? team_size(threads_) : 1);
    resize_sorted(s.size());
    const int nc = cells_.cells();
    cell_sums_.resize(std::size_t(nc));
    layer_force2_.assign(std::size_t(cells_.layers()), 0.0);
    const bool tap = cx.tap != nullptr;
    if (tap) cell_tap_.resize(std::size_t(nc));
    if (cx.in_tap) cell_in_range_.resize(std::size_t(nc));
    const bool stream = noise_->stream();
    slot_base_.assign(stream ? std::size_t(nc) + 1 : 0, 0);
    // One region for the step's pair forces: three barriers (inside the sort, after it, after the gather;
    // the stream reference adds two), then the layers, which wait for their neighbours only, then the join.
#pragma omp parallel num_threads(team_size(threads_)) if (team)
    {
      cells_.sort(s);
      // The team actually granted, which OMP_THREAD_LIMIT or an enclosing region can make smaller than asked:
      // a queue without a thread behind it could hold an even layer that an odd one waits for forever.
#pragma omp single
      reset_layers(omp_get_num_threads());
      gather(s, cx.v, cx.conf);
#pragma omp barrier
      if (stream) number_pairs(s.box);
      if (zero_)
        run_layers<true>(cx, tap);
      else
        run_layers<false>(cx, tap);
    }
    ForceSums sums;
    sums.min_r2 = k_.rc2();
    for (const CellSums& cs : cell_sums_) {
      for (int a = 0; a < 3; ++a) sums.virial[a] += cs.w[a], sums.virial_cons[a] += cs.wc[a];
      sums.min_r2 = std::min(sums.min_r2, cs.min_r2);
      sums.in_range += cs.count;
      sums.candidates += cs.candidates;
      sums.zeta.merge(cs.zeta);
      sums.conf_laplacian += cs.laplacian;
    }
    sums.conf_laplacian *= 2.0;  // each pair's ∇²u counts for both its beads
    for (const double f2 : layer_force2_) sums.conf_force2 += f2;
    sums.configurational = cx.conf;
    if (tap)
      for (int w = 0; w < words_; ++w) cx.tap->words[w].clear();
    if (tap)
      for (int c = 0; c < nc; ++c)
        for (int w = 0; w < words_; ++w)
          cx.tap->words[w].insert(cx.tap->words[w].end(), cell_tap_[c][w].begin(), cell_tap_[c][w].end());
    return sums;
  }

  // The stream reference needs every pair's slot, in the fixed pair order, before any layer runs.
  void number_pairs(const Box& box) {
    const int nc = cells_.cells();
#pragma omp for schedule(dynamic, 8)
    for (int c = 0; c < nc; ++c) slot_base_[c + 1] = count_cell(box, c, scratch_[omp_get_thread_num()]);
#pragma omp single
    {
      for (int c = 0; c < nc; ++c) slot_base_[c + 1] += slot_base_[c];
      noise_->begin_step(slot_base_[nc]);
    }
  }

  // Each worker's queue of layers: its own block's even layers, then its odd ones (a single layer when the box
  // has no grid). A box with few layers per colour runs on one worker (the result does not depend on the
  // team size, so this choice is free). Every worker must be a thread of the team that runs the layers.
  void reset_layers(int team) {
    const int layers = cells_.layers(), colours = cells_.colours();
    workers_ = layers / colours >= 2 * team ? team : 1;
    items_.clear(), queue_.assign(std::size_t(workers_) + 1, 0), cursor_.assign(std::size_t(workers_) * kLine, 0);
    for (int w = 0; w < workers_; ++w) {
      const auto [z0, z1] = own_layers(w, workers_);
      for (int colour = 0; colour < colours; ++colour)
        for (int z = z0; z < z1; ++z)
          if (z % colours == colour) items_.push_back(z);
      queue_[w + 1] = int(items_.size());
      cursor_[std::size_t(w) * kLine] = queue_[w];
    }
    done_.assign(std::size_t(layers), 0);
    pending_.assign(std::size_t(layers), 2);
  }

  // The next layer for thread t: from its own queue, else taken from another worker's (in that queue's
  // order, so every even layer is claimed before any odd one of the same queue), or −1 when all are claimed.
  int claim(int t) {
    for (int u = 0; u < workers_; ++u) {
      const int w = (t + u) % workers_;
      const int q = std::atomic_ref<int>(cursor_[std::size_t(w) * kLine]).fetch_add(1, std::memory_order_relaxed);
      if (q < queue_[w + 1]) return items_[q];
    }
    return -1;
  }

  // Layer z's cells write forces to layers z and z + 1 only, so the even layers run side by side, and an odd
  // layer may start once its two even neighbours are done: the same order of contributions for every bead
  // as two colours with a barrier between them (even layers first), without the barrier: a thread that
  // finishes early, or whose partner the host has paused, takes the other's remaining layers. No claimed
  // even layer waits for anything, so an odd one's wait always ends. A layer's forces are final once it
  // and the layer before it are done; the thread that completes the second copies them to the System.
  template <bool Zero>
  void run_layers(const Ctx& cx, bool tap) {
    const int layers = cells_.layers();
    const int thread = omp_get_thread_num();
    if (thread >= workers_) return;
    for (int z; (z = claim(thread)) >= 0;) {
      if (z % cells_.colours() != 0) await_layer(z - 1), await_layer((z + 1) % layers);
      do_layer<Zero>(cx, z, thread, tap);
      std::atomic_ref<int>(done_[z]).store(1, std::memory_order_release);
      contributed(cx.s, z, cx.conf), contributed(cx.s, (z + 1) % layers, cx.conf);
    }
  }

  void await_layer(int z) {
    std::atomic_ref<int> done(done_[z]);
    wait_until([&] { return done.load(std::memory_order_acquire) != 0; });
  }

  // One of layer z's two contributors is done; the thread completing the second scatters the layer, one array
  // at a time (as gather).
  void contributed(System& s, int z, bool conf) {
    if (std::atomic_ref<int>(pending_[z]).fetch_sub(1, std::memory_order_acq_rel) != 1) return;
    const int per_layer = cells_.layer_cells();
    const std::uint32_t* order = cells_.order().data();
    const std::uint32_t lo = cells_.begin(z * per_layer), hi = cells_.end((z + 1) * per_layer - 1);
    permuted::scatter(order, lo, hi, fxs_.data(), s.fx.data());
    permuted::scatter(order, lo, hi, fys_.data(), s.fy.data());
    permuted::scatter(order, lo, hi, fzs_.data(), s.fz.data());
    double force2 = 0;
    if (conf)
      for (std::uint32_t k = lo; k < hi; ++k) force2 += fcx_[k] * fcx_[k] + fcy_[k] * fcy_[k] + fcz_[k] * fcz_[k];
    layer_force2_[std::size_t(z)] = force2;
  }

  ForceSums reduce(System& s, bool conf) {
    ForceSums sums;
    sums.min_r2 = k_.rc2();
    for (std::size_t i = 0; i < s.size(); ++i) {
      const Row& row = rows_[i];
      for (std::uint32_t t = 0; t < row.count; ++t) {
        const Rec& r = row.rec[t];
        s.fx[r.j] -= r.fx, s.fy[r.j] -= r.fy, s.fz[r.j] -= r.fz;
      }
      if (conf)
        for (std::uint32_t t = 0; t < row.count; ++t) {
          const std::uint32_t j = row.rec[t].j;
          fcx_[j] -= row.conf[t][0], fcy_[j] -= row.conf[t][1], fcz_[j] -= row.conf[t][2];
        }
      for (int a = 0; a < 3; ++a) sums.virial[a] += row.w[a], sums.virial_cons[a] += row.wc[a];
      sums.min_r2 = std::min(sums.min_r2, row.min_r2);
      sums.in_range += row.count;
      sums.zeta.merge(row.zeta);
      sums.conf_laplacian += row.laplacian;
    }
    sums.conf_laplacian *= 2.0;  // each pair's ∇²u counts for both its beads
    if (conf)
      for (std::size_t i = 0; i < s.size(); ++i)
        sums.conf_force2 += fcx_[i] * fcx_[i] + fcy_[i] * fcy_[i] + fcz_[i] * fcz_[i];
    sums.configurational = conf;
    return sums;
  }

  // Hashes are pure functions of the pair input, so a tapped pair's block is recomputed here from the same
  // separation the loop used; the stream reference reads the pair's slot (all mode only, checked by validate).
  static rng::PairInput pair_input(const System& s, std::uint32_t i, std::uint32_t j, std::uint64_t step) {
    const double Lx = s.box.L[0], Ly = s.box.L[1], Lz = s.box.L[2];
    const double dx = min_image(s.x[j] - s.x[i], Lx, Lx / 2), dy = min_image(s.y[j] - s.y[i], Ly, Ly / 2),
                 dz = min_image(s.z[j] - s.z[i], Lz, Lz / 2);
    return {i, j, dx, dy, dz, step};
  }

  // Whether batch_of serves this noise: a hash, or the stream in all mode.
  bool batches() const { return !zero_ && (!noise_->stream() || mode_ == PairMode::all); }

  // Noise on pairs (i[t], j[t]), i < j, at this step: ζ into zeta and, when tap[0] is given, the blocks' words
  // into tap[w], in one batch through the noise kernel (canonical() leaves such pairs as they are, and the stream
  // reads each pair's slot, so the blocks are NoiseKernel::pair's). Runs outside the parallel regions, on thread
  // 0's scratch; the stream's step must have begun (compute of this step).
  void batch_of(const System& s, const std::uint32_t* i, const std::uint32_t* j, std::size_t n, std::uint64_t step,
                double* zeta, std::array<std::uint64_t*, 2> tap) const {
    BatchInputs& in = batch_inputs_;
    in.dx.resize(n), in.dy.resize(n), in.dz.resize(n);
    for (std::size_t t = 0; t < n; ++t) {
      const rng::PairInput p = pair_input(s, i[t], j[t], step);
      in.dx[t] = p.dx, in.dy[t] = p.dy, in.dz[t] = p.dz;
    }
    const bool stream = noise_->stream();
    if (stream) {
      in.slots.resize(n);
      for (std::size_t t = 0; t < n; ++t) in.slots[t] = pair_slot(i[t], j[t], s.size());
    }
    noise_->pairs({i, j, n, in.dx.data(), in.dy.data(), in.dz.data(), step, 0, {tap[0], tap[1]}, zeta, nullptr,
                   stream ? in.slots.data() : nullptr},
                  0);
  }

  void record_series(const System& s, std::uint64_t step, Taps& taps) const {
    if (taps.series.size() != tap_pairs_.size()) {
      taps.series.resize(tap_pairs_.size());
      for (std::size_t q = 0; q < tap_pairs_.size(); ++q) {
        taps.series[q].i = tap_pairs_[q].first, taps.series[q].j = tap_pairs_[q].second;
        taps.series[q].words_per_pair = words_;
        reserve_series(taps.series[q]);
      }
    }
    if (batches() && series_ordered_) return record_series_batch(s, step, taps);
    for (auto& ser : taps.series) {
      const std::uint32_t i = ser.i, j = ser.j;
      std::uint64_t words[2] = {0, 0};
      double zeta = 0;
      noise_->pair(pair_input(s, i, j, step), pair_slot(i, j, s.size()), words, zeta);
      ser.steps.push_back(static_cast<std::int64_t>(step));
      for (int w = 0; w < words_; ++w) ser.words[w].push_back(words[w]);
      ser.zeta.push_back(zeta);
    }
  }

  // Room for the run's production steps (series_steps_) up front: no vector of a series is copied as it grows.
  void reserve_series(PairSeries& ser) const {
    ser.steps.reserve(series_steps_), ser.zeta.reserve(series_steps_);
    for (int w = 0; w < words_; ++w) ser.words[std::size_t(w)].reserve(series_steps_);
  }

  // record_series in one batch (batch_of), into the stage: a step's values side by side, so that a step writes
  // a few cache lines, not one in each of the series' vectors.
  void record_series_batch(const System& s, std::uint64_t step, Taps& taps) const {
    const std::size_t n = taps.series.size();
    BatchInputs& in = batch_inputs_;
    SeriesStage& st = stage_;
    if (in.i.size() != n) {
      in.i.resize(n), in.j.resize(n);
      for (std::size_t q = 0; q < n; ++q) in.i[q] = taps.series[q].i, in.j[q] = taps.series[q].j;
      st.zeta.resize(SeriesStage::kSteps * n);
      for (int w = 0; w < words_; ++w) st.words[std::size_t(w)].resize(SeriesStage::kSteps * n);
    }
    const std::size_t at = st.steps.size() * n;
    std::array<std::uint64_t*, 2> tap{st.words[0].data() + at, words_ > 1 ? st.words[1].data() + at : nullptr};
    batch_of(s, in.i.data(), in.j.data(), n, step, st.zeta.data() + at, tap);
    st.steps.push_back(static_cast<std::int64_t>(step));
    if (st.steps.size() == SeriesStage::kSteps) flush_stage(taps);
  }

  // The staged steps appended to each series, in step order: one array of the stage at a time, so that its
  // kSteps rows stay in L1 while every series takes its column.
  void flush_stage(Taps& taps) const {
    SeriesStage& st = stage_;
    const std::size_t n = taps.series.size(), m = st.steps.size();
    for (auto& ser : taps.series) ser.steps.insert(ser.steps.end(), st.steps.begin(), st.steps.end());
    for (std::size_t q = 0; q < n; ++q) append_column(st.zeta.data() + q, n, m, taps.series[q].zeta);
    for (std::size_t w = 0; w < std::size_t(words_); ++w)
      for (std::size_t q = 0; q < n; ++q) append_column(st.words[w].data() + q, n, m, taps.series[q].words[w]);
    st.steps.clear();
  }

  // m values `stride` apart from `first`, appended to `out` (its room reserved: no reallocation).
  template <class T>
  static void append_column(const T* first, std::size_t stride, std::size_t m, std::vector<T>& out) {
    const std::size_t at = out.size();
    out.resize(at + m);
    T* o = out.data() + at;
    for (std::size_t c = 0; c < m; ++c) o[c] = first[c * stride];
  }

  // batch_of's and record_series_batch's buffers (serial callers only).
  struct BatchInputs {
    std::vector<std::uint32_t> i, j;
    std::vector<double> dx, dy, dz;
    std::vector<std::size_t> slots;
  };
  mutable BatchInputs batch_inputs_;
  // The pair series' latest steps (record_series_batch), step-major: steps[c]'s values at [c·pairs, (c+1)·pairs).
  struct SeriesStage {
    static constexpr std::size_t kSteps = 64;
    std::vector<std::int64_t> steps;
    std::vector<double> zeta;
    std::array<std::vector<std::uint64_t>, 2> words;
  };
  mutable SeriesStage stage_;

  std::unique_ptr<NoiseKernel> noise_;
  bool zero_;
  int words_;
  DpdKernel k_;
  PairMode mode_;
  int threads_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> tap_pairs_;
  std::size_t series_steps_;
  bool series_ordered_ = false;  // every tapped pair has i < j (record_series' batch keeps their blocks)
  std::vector<Row> rows_;  // all mode
  std::vector<double> fcx_, fcy_, fcz_;  // the conservative force per bead (cells mode: in sorted order)
  std::vector<float> xf_, yf_, zf_;      // all mode: the positions rounded (round_positions)
  float threshold_f_ = 0;
  bool grid_ = false;                                   // all mode: this step's prefilter is the grid's
  std::array<std::vector<std::uint16_t>, 3> grid_pos_;  // its coordinates (round_positions)
  std::uint16_t threshold_g_ = 0;
  std::vector<double> layer_force2_;     // cells mode: Σ|F^C|² over each layer's beads
  std::vector<Scratch> scratch_;
  // cells mode
  SortedCells cells_;
  std::vector<double> xs_, ys_, zs_, vxs_, vys_, vzs_, fxs_, fys_, fzs_;
  std::vector<std::uint8_t> types_;
  std::vector<CellSums> cell_sums_;
  std::vector<std::uint64_t> slot_base_;
  // The layers' schedule (reset_layers), used through atomic_ref: per layer, done and contributors pending;
  // per worker, its queue items_[queue_[w], queue_[w + 1]) and its cursor, a cache line apart from the others.
  static constexpr std::size_t kLine = 16;
  int workers_ = 1;
  std::vector<int> done_, pending_, items_, queue_, cursor_;
  std::vector<std::array<std::vector<std::uint64_t>, 2>> cell_tap_;
  std::vector<InRangeTap> cell_in_range_;  // cells mode: each cell's part of the step's tap
};

}  // namespace

std::unique_ptr<PairForces> make_pair_loop(std::unique_ptr<NoiseKernel> noise, const DpdKernel& kernel,
                                           PairMode mode, int threads, std::size_t n,
                                           std::vector<std::pair<std::uint32_t, std::uint32_t>> tap_pairs,
                                           std::size_t series_steps) {
  return std::make_unique<PairLoop>(std::move(noise), kernel, mode, threads, n, std::move(tap_pairs), series_steps);
}

}  // namespace dpdrng::dpd
