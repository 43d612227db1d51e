#pragma once
// A generator with a known, injected defect, for measuring what the study's verdicts can detect: a good hash
// (Philox4x32-10) whose ζ is altered on purpose. With η_t the base's ζ for a pair at step t,
//   ζ_t = μ + √(1+ε) · (a·η_{t−1} + √(1−a²)·η_t),  a·√(1−a²) = ρ, |ρ| ≤ 1/2 (the most an MA(1) can correlate)
// so that ⟨ζ⟩ = μ, ⟨ζ²⟩ − μ² = 1 + ε and corr(ζ_t, ζ_{t−1}) = ρ (for η of zero mean and unit variance). An
// anisotropic defect of size κ multiplies the fluctuating part by √(1 + κ(3 cos²θ − 1)), θ the angle between the
// pair's separation and z: ζ's variance depends on the pair's direction while its mean over isotropic directions
// stays 1 + ε (⟨3 cos²θ − 1⟩ = 0), so it moves T_z against T_x and T_y (and P_zz against P_xx, P_yy) far more
// than it moves k_BT. It needs the separation, hence distance seeding. It stays
// a stateless hash: η_{t−1} is the base hash of the same pair at step t − 1, recomputed, not remembered, so the
// numbers do not depend on the thread count. In counter mode (standalone streams) "step" is the call index.
//
// The defect lives at the level of ζ. The words (gen, NIST, χ² of words, the pair taps) are the base's words
// unchanged: mapping a defective ζ back to words would give a different word-level defect for every
// distribution, while the word-level tests are meant to judge the hash, and the hash here is Philox4x32-10.
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include "dpdrng/rng/distribution.hpp"
#include "dpdrng/rng/random123.hpp"

namespace dpdrng::rng {

struct DefectParams {
  double variance = 0;  // ε: ⟨ζ²⟩ − ⟨ζ⟩² = 1 + ε
  double lag1 = 0;      // a, the weight of η_{t−1}: parse_defect solves a·√(1−a²) = ρ for the ρ asked for
  double mean = 0;      // μ: ⟨ζ⟩
  double aniso = 0;     // κ: the variance along z is (1 + 2κ)/(1 − κ) times the variance in the x-y plane
  // key=N: N replaces the second word of the base's key, so that defect:key=N for distinct N are independent
  // good generators (the null variants of a calibration at a study's own size); -1 keeps the generator's key.
  std::int64_t key = -1;

  double scale() const { return std::sqrt(1.0 + variance); }
  double fresh() const { return std::sqrt(1.0 - lag1 * lag1); }
};

// "defect:variance=0.01,lag1=0.1,mean=0.02,aniso=0.1,key=7,base=philox4x32": keys in any order, each at most
// once, all optional (key an integer in [0, 2^32)); base = philox4x32 (10 rounds) is the only base. InputError naming the fault otherwise (ε ≤ −1,
// |ρ| > 1/2, κ outside (−1/2, 1) where a direction's variance would not be positive, a non-finite number, an
// unknown key).
inline constexpr std::string_view kDefectPrefix = "defect:";
bool is_defect(std::string_view name);  // "defect" or "defect:..."
DefectParams parse_defect(std::string_view name);
std::string defect_syntax();  // one line for --help and `dpdrng list`

// The base's two words of step t (now) and, when ρ ≠ 0, of step t − 1 (prev), with the parameters that turn
// them into ζ (draw below). Indexing and iteration give the words of step t: the word-level stream.
struct DefectBlock {
  std::array<std::uint64_t, 2> now{}, prev{};
  DefectParams p;
  double direction = 1;  // √(1 + κ(3 cos²θ − 1)) of the pair (1 without an anisotropic defect)

  std::uint64_t operator[](std::size_t w) const { return now[w]; }
  auto begin() const { return now.begin(); }
  auto end() const { return now.end(); }
  static constexpr std::size_t size() { return 2; }
};

struct Defect {
  static constexpr const char* kName = "defect";
  static constexpr int kWords = 2;
  using Block = DefectBlock;
  using Base = Philox4x32<10>;

  Base base;
  DefectParams p;
  static DefectParams params(std::string_view name) { return parse_defect(name); }
  TeaKey key = kPaperTeaKey;  // the base's key
  int rounds = 1;

  Block stream(std::uint64_t start, std::uint64_t i) const {
    return {b().stream(start, i), p.lag1 != 0 ? b().stream(start, i - 1) : Base::Block{}, p};
  }
  // Distance seeding has no step, hence no previous step: a lag-1 defect needs pair-step seeding, which
  // check_defect_seeding (registry.hpp) enforces before a run starts.
  Block distance(double dx, double dy, double dz) const {
    return {b().distance(dx, dy, dz), {}, p, direction_factor(p.aniso, dx, dy, dz)};
  }
  Block pair_step(std::uint32_t i, std::uint32_t j, std::uint64_t step, std::uint64_t seed) const {
    return {b().pair_step(i, j, step, seed), p.lag1 != 0 ? b().pair_step(i, j, step - 1, seed) : Base::Block{}, p};
  }

  // √(1 + κ(3 cos²θ − 1)), cos θ = dz/r; a pair at zero separation counts as isotropic.
  static double direction_factor(double kappa, double dx, double dy, double dz) {
    if (kappa == 0) return 1;
    const double r2 = dx * dx + dy * dy + dz * dz;
    const double c2 = r2 > 0 ? dz * dz / r2 : 1.0 / 3.0;
    return std::sqrt(1 + kappa * (3 * c2 - 1));
  }

 private:
  Base b() const {
    Base g;
    g.key = key;
    if (p.key >= 0) g.key[1] = static_cast<std::uint32_t>(p.key);
    return g;
  }
};

// The registry's "defect" entry; a run names its parameters (defect:...), which the registry parses.
template <>
struct FamilyTraits<Family::defect> {
  template <int>
  using Gen = Defect;
  using CompiledRounds = Rounds<>;
  static constexpr GeneratorInfo kInfo{
      .name = "defect",
      .family = Family::defect,
      .safe_rounds = "a test article with a known defect, not for production",
      .description = "Philox4x32-10 with an injected defect at the level of zeta (variance, lag-1 correlation or "
                     "mean shift); its words are Philox's. Name: defect:variance=E,lag1=R,mean=M,base=philox4x32"};
};

template <Distribution D>
inline double draw(const DefectBlock& b) {
  double eta = draw<D>(b.now);
  if (b.p.lag1 != 0) eta = b.p.lag1 * draw<D>(b.prev) + b.p.fresh() * eta;
  return b.p.mean + b.p.scale() * b.direction * eta;
}

// Under a feed chosen at run time: η from the base's blocks through that feed (b is the second block, read only
// by the blocks feed), then the same defect.
template <Distribution D>
inline double draw(Feed f, const DefectBlock& a, const DefectBlock& b) {
  double eta = draw<D>(f, a.now, b.now);
  if (a.p.lag1 != 0) eta = a.p.lag1 * draw<D>(f, a.prev, b.prev) + a.p.fresh() * eta;
  return a.p.mean + a.p.scale() * a.direction * eta;
}

}  // namespace dpdrng::rng
