// The batched paths against the scalar definitions, all bit for bit: integer outputs, uniform and Gaussian numbers.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>
#include <vector>

#include "dpdrng/rng/batch.hpp"
#include "dpdrng/rng/dispatch.hpp"
#include "dpdrng/rng/mt.hpp"
#include "dpdrng/rng/stream.hpp"
#include "every_generator.hpp"

namespace dpdrng_test::rng_test_batch {

using namespace dpdrng::rng;

namespace {

// Every generator at its interesting round counts (every_generator.hpp), mt19937 included, plus the counts where
// Threefry's batched key injection (every 4 rounds) and Philox's round loop change shape. Each with a key other
// than the paper's, so that key handling is tested too.
std::vector<GeneratorSpec> all_specs() {
  std::vector<GeneratorSpec> out = dpdrng_test::every_generator(true, true);
  for (int r : {4, 5, 12}) out.push_back(validated({"threefry2x64", r}));
  out.push_back(validated({"philox4x32", 6}));
  for (auto& s : out) s.key = {0x9e3779b9u, 7u, 0xdeadbeefu, 0x12345678u};
  return out;
}

// Word k of the stream from its definition: call k / W of stream(), or mt19937's k-th next64().
std::vector<std::uint64_t> scalar_words(const GeneratorSpec& s, std::uint64_t start, std::size_t n) {
  std::vector<std::uint64_t> out(n);
  if (s.name == "mt19937") {
    Mt19937 mt(start);
    for (auto& w : out) w = mt.next64();
    return out;
  }
  with_hash(s, [&](const auto& g) {
    const std::size_t W = std::decay_t<decltype(g)>::kWords;
    for (std::size_t k = 0; k < n; ++k) out[k] = g.stream(start, k / W)[k % W];
  });
  return out;
}

// Lengths and offsets that cross the 8-, 16- and 32-call blocks and start inside a two-word call.
TEST(Batch, FillStreamEqualsScalarBitwise) {
  constexpr std::uint64_t kStart = 0xfffffffffffffff0ull;  // the counter wraps and its low word carries mid-block
  for (const auto& s : all_specs()) {
    const auto ref = scalar_words(s, kStart, 300);
    for (std::size_t offset : {0, 1, 3, 17}) {
      for (std::size_t len : {0, 1, 15, 16, 31, 33, 64, 200}) {
        std::vector<std::uint64_t> got(len);
        fill_stream(s, kStart, offset, got);
        for (std::size_t k = 0; k < len; ++k)
          ASSERT_EQ(got[k], ref[offset + k]) << describe(s) << " offset " << offset << " len " << len << " k " << k;
      }
    }
  }
}

TEST(Batch, Tea32HashBatchEqualsScalar) {
  std::mt19937_64 pick(5);
  std::vector<std::uint64_t> seeds(77), out(77);
  for (auto& s : seeds) s = pick();
  auto check = [&](const auto& g) {
    hash_batch(g, seeds, out);
    for (std::size_t k = 0; k < seeds.size(); ++k) ASSERT_EQ(out[k], g.hash(seeds[k])) << k;
  };
  check(Tea32<1>{});
  check(Tea32<8>{});
  Tea32<0> dyn;
  dyn.rounds = 11;
  check(dyn);
}

// The pair loop's batch members of the built-in TEAs against distance() and pair_step() pair by pair: every
// compiled round count and a run-time one, a key other than the paper's, separations of both signs with
// subnormal and zero components, ids across the whole 32-bit range, steps past 2^32, batch lengths that take
// each of the batch's paths (two registers, one, a tail padded or call by call) alone and together.
template <class G>
void expect_pair_batches_equal_scalar(G g) {
  g.key = {0x9e3779b9u, 7u, 0xdeadbeefu, 0x12345678u};
  std::mt19937_64 pick(23);
  std::uniform_real_distribution<double> sep(-1.0, 1.0);
  for (std::size_t n : {133, 53, 29, 16, 7, 0}) {
    std::vector<double> dx(n), dy(n), dz(n);
    std::vector<std::uint32_t> i(n), j(n);
    for (std::size_t t = 0; t < n; ++t) {
      dx[t] = sep(pick), dy[t] = sep(pick), dz[t] = sep(pick);
      i[t] = static_cast<std::uint32_t>(pick()), j[t] = static_cast<std::uint32_t>(pick());
    }
    if (n > 3) dx[0] = 0.0, dy[1] = -0.0, dx[2] = 4.9e-324, dy[3] = -2.2e-308;
    std::vector<typename G::Block> got(n);
    g.distance_batch(dx.data(), dy.data(), dz.data(), n, got.data());
    for (std::size_t t = 0; t < n; ++t) ASSERT_EQ(got[t], g.distance(dx[t], dy[t], dz[t])) << G::kName << " " << t;
    for (const std::uint64_t step : {std::uint64_t{0}, std::uint64_t{123456789012}, ~std::uint64_t{5}}) {
      g.pair_step_batch(i.data(), j.data(), step, 0xabcdef0123ull, n, got.data());
      for (std::size_t t = 0; t < n; ++t)
        ASSERT_EQ(got[t], g.pair_step(i[t], j[t], step, 0xabcdef0123ull)) << G::kName << " " << t;
    }
  }
}

template <template <int> class G, int... R>
void expect_pair_batches_at(Rounds<R...>) {
  (expect_pair_batches_equal_scalar(G<R>{}), ...);
  G<0> dyn;
  dyn.rounds = 11;
  expect_pair_batches_equal_scalar(dyn);
}

TEST(Batch, TeaPairBatchesEqualScalar) {
  expect_pair_batches_at<Tea32>(TeaCompiledRounds{});
  expect_pair_batches_at<Tea64>(TeaCompiledRounds{});
}

std::vector<double> scalar_noise(const GeneratorSpec& s, Distribution d, std::uint64_t start, std::uint64_t first,
                                 std::size_t n) {
  std::vector<double> out(n);
  auto draw_block = [&](const auto& b) {
    return d == Distribution::gauss ? draw<Distribution::gauss>(b) : draw<Distribution::uniform>(b);
  };
  if (s.name == "mt19937") {
    Mt19937 mt(start);
    mt.engine.discard(2 * first);
    for (auto& x : out) x = draw_block(std::array<std::uint64_t, 1>{mt.next64()});
    return out;
  }
  with_hash(s, [&](const auto& g) {
    for (std::size_t k = 0; k < n; ++k) out[k] = draw_block(g.stream(start, first + k));
  });
  return out;
}

TEST(Batch, FillUniformEqualsScalarDrawBitwise) {
  for (const auto& s : all_specs()) {
    const auto ref = scalar_noise(s, Distribution::uniform, 99, 5, 1100);
    std::vector<double> got(1100);
    fill_uniform(s, 99, 5, got);
    for (std::size_t k = 0; k < got.size(); ++k) ASSERT_EQ(got[k], ref[k]) << describe(s) << " k " << k;
  }
}

// The batched Gaussian runs box_muller_parts() in vectorised loops and the SIMD sqrt; the pair loop calls the
// scalar box_muller(). Both must give the same ζ for the same block: compared bit for bit, over lengths that
// leave a tail shorter than a SIMD block.
TEST(Batch, FillGaussEqualsScalarBoxMullerBitwise) {
  for (const auto& s : all_specs()) {
    for (std::size_t len : {2000, 13}) {
      const auto ref = scalar_noise(s, Distribution::gauss, 3, 7, len);
      std::vector<double> got(len);
      fill_gauss(s, 3, 7, got);
      for (std::size_t k = 0; k < got.size(); ++k) ASSERT_EQ(got[k], ref[k]) << describe(s) << " k " << k;
    }
  }
}

// The pair loop's two-word Box–Muller (the blocks feed, and the halves of two-word blocks) eight at a time
// against the scalar box_muller, bit for bit: random words, the words at the ends of the unit interval (u1 = 2^-53
// and 1, u2 = 0 and just below 1), and lengths that leave a tail shorter than a register.
TEST(Batch, TwoWordBoxMullerEqualsScalarBitwise) {
  std::mt19937_64 eng(35);
  for (std::size_t len : {1001, 8, 7, 0}) {
    std::vector<std::uint64_t> u1(len), u2(len);
    for (std::size_t k = 0; k < len; ++k) u1[k] = eng(), u2[k] = eng();
    const std::uint64_t edges[] = {0, ~0ull, 1ull << 11, (1ull << 11) - 1};
    for (std::size_t k = 0; k < len && k < 16; ++k) u1[k] = edges[k % 4], u2[k] = edges[(k / 4) % 4];
    std::vector<double> got(len);
    box_muller_two_words(u1.data(), u2.data(), len, got.data());
    for (std::size_t k = 0; k < len; ++k) {
      const double ref = box_muller(std::array<std::uint64_t, 2>{u1[k], u2[k]});
      ASSERT_EQ(std::bit_cast<std::uint64_t>(got[k]), std::bit_cast<std::uint64_t>(ref)) << "len " << len << " k " << k;
      ASSERT_TRUE(std::isfinite(got[k]));
    }
  }
}

TEST(Batch, FillUnitIsToUnitOfTheStream) {
  GeneratorSpec s;
  s.name = "tea64";
  s = validated(s);
  const auto words = scalar_words(s, 0, 101);
  std::vector<double> got(100);
  fill_unit(s, 0, 1, got);
  for (std::size_t k = 0; k < got.size(); ++k) ASSERT_EQ(got[k], to_unit(words[k + 1]));
}

}  // namespace

}  // namespace dpdrng_test::rng_test_batch
