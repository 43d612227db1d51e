// The batched paths against the scalar definitions, all bit for bit: integer outputs, uniform and Gaussian numbers.
#include <gtest/gtest.h>

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
