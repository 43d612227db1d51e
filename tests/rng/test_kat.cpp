// Known-answer tests: every generator against published vectors, each table naming its source.
#include <gsl/gsl_rng.h>
#include <gtest/gtest.h>

#include <Random123/philox.h>
#include <Random123/threefry.h>
#include <array>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "dpdrng/rng/mt.hpp"
#include "dpdrng/rng/random123.hpp"
#include "dpdrng/rng/splitmix.hpp"
#include "dpdrng/rng/tea.hpp"

namespace dpdrng_test::rng_test_kat {

using namespace dpdrng::rng;

namespace {

// ---- TEA, 32 cycles -----------------------------------------------------------------------------------------
// Bouncy Castle, core/src/test/java/org/bouncycastle/crypto/test/TEATest.java ("based on C implementation
// results from simonshepherd.supanet.com/tea.htm"). Key and blocks there are big-endian byte strings: key
// "0123456712345678234567893456789A" is k0..k3 = 0x01234567, 0x12345678, 0x23456789, 0x3456789A and block
// "0102030405060708" is v0 = 0x01020304, v1 = 0x05060708.
struct TeaVector {
  TeaKey key;
  std::uint32_t v0, v1, e0, e1;
};
constexpr TeaVector kTeaVectors[] = {
    {{0, 0, 0, 0}, 0x00000000, 0x00000000, 0x41ea3a0a, 0x94baa940},
    {{0, 0, 0, 0}, 0x01020304, 0x05060708, 0x6a2f9cf3, 0xfccf3c55},
    {{0x01234567, 0x12345678, 0x23456789, 0x3456789A}, 0x00000000, 0x00000000, 0x34e943b0, 0x900f5dcb},
    {{0x01234567, 0x12345678, 0x23456789, 0x3456789A}, 0x01020304, 0x05060708, 0x773dc179, 0x878a81c0},
};

TEST(KatTea, BouncyCastleVectors32Cycles) {
  for (const auto& t : kTeaVectors) {
    std::uint32_t x0 = t.v0, x1 = t.v1;
    tea_encrypt<32>(x0, x1, t.key);
    EXPECT_EQ(x0, t.e0);
    EXPECT_EQ(x1, t.e1);
    // The same vector through 32TEA(32): v0 is the seed's low word, the output joins (x1' << 32) | x0'.
    Tea32<32> g;
    g.key = t.key;
    EXPECT_EQ(g.hash(join32(t.v1, t.v0)), join32(t.e1, t.e0));
    Tea32<0> dyn;
    dyn.key = t.key;
    dyn.rounds = 32;
    EXPECT_EQ(dyn.hash(join32(t.v1, t.v0)), join32(t.e1, t.e0));
  }
}

// 64TEA is the same cycle on 64-bit words: with every word below 2^32 and no carries reaching bit 32 it would
// agree with TEA, but it does not in general; so here: its round function against docs/design.md's equations for
// several cycles, and the paper's join (a, b) = (x0', x1').
TEST(KatTea, Tea64FollowsTheRoundEquationsForManyCycles) {
  const std::array<std::uint64_t, 4> k{3, 4, 5, 6};
  std::uint64_t x0 = 0x0123456789abcdefull, x1 = 0xfedcba9876543210ull, sum = 0;
  for (int r = 0; r < 5; ++r) {
    sum += 0x9E3779B9ull;
    x0 += ((x1 << 4) + k[0]) ^ ((x1 >> 5) + k[1]) ^ (x1 + sum);
    x1 += ((x0 << 4) + k[2]) ^ ((x0 >> 5) + k[3]) ^ (x0 + sum);
  }
  const auto ab = Tea64<5>{}.hash(0x0123456789abcdefull, 0xfedcba9876543210ull, Tea64<5>{}.key64());
  EXPECT_EQ(ab[0], x0);
  EXPECT_EQ(ab[1], x1);
}

// ---- Philox4x32 and Threefry2x64 ----------------------------------------------------------------------------
// Random123's examples/kat_vectors (read from the copy in github.com/girving/random123-manual), one row per
// line there: name, rounds, counter words, key words, expected words, all hex.
struct PhiloxRow {
  int rounds;
  std::array<std::uint32_t, 4> ctr;
  std::array<std::uint32_t, 2> key;
  std::array<std::uint32_t, 4> expect;
};
constexpr PhiloxRow kPhilox[] = {
    {7, {0x00000001, 0x00000000, 0x00000000, 0x00000000}, {0x00000001, 0x00000000},
     {0x6b3257c3, 0x820c5486, 0x4de08b66, 0x8771d665}},
    {7, {0x243f6a88, 0x85a308d3, 0x13198a2e, 0x03707344}, {0x00000001, 0x00000000},
     {0x64803f9b, 0xacd38b4b, 0x5ea00643, 0x770c3921}},
    {7, {0x452821e6, 0x38d01377, 0xbe5466cf, 0x34e90c6c}, {0x00000000, 0xffffffff},
     {0x9ea5c780, 0x92dfd935, 0x5f5021d0, 0x891581d8}},
    {7, {0x00000000, 0x00000000, 0x00000000, 0x80000000}, {0x00000000, 0x80000000},
     {0x323abc61, 0x28b9f4ce, 0x59d8d353, 0x01a9cf42}},
    {10, {0x00000001, 0x00000000, 0x00000000, 0x00000000}, {0x00000001, 0x00000000},
     {0xac08141b, 0xdfc5ccbe, 0x79c07a47, 0xa7f66093}},
    {10, {0x243f6a88, 0x85a308d3, 0x13198a2e, 0x03707344}, {0x00000001, 0x00000000},
     {0x38527b8f, 0xfad9a48c, 0x20e675c0, 0xf2fea26a}},
    {10, {0xa4093822, 0x299f31d0, 0x082efa98, 0xec4e6c89}, {0x00000000, 0x00000001},
     {0x1c28fa3f, 0x8c5bf977, 0xbb989783, 0x0c1a3737}},
    {10, {0x452821e6, 0x38d01377, 0xbe5466cf, 0x34e90c6c}, {0x00000000, 0x80000000},
     {0x94ca5566, 0x14924b2f, 0x28214292, 0x59faeaee}},
    {10, {0x00000000, 0xffffffff, 0x00000000, 0x00000000}, {0x00000000, 0xffffffff},
     {0x5f9c47aa, 0x19861d86, 0xff2be81d, 0x4c7db17e}},
};

struct ThreefryRow {
  int rounds;
  std::array<std::uint64_t, 2> ctr, key, expect;
};
constexpr ThreefryRow kThreefry[] = {
    {13, {0x0000000000000001, 0}, {0x0000000000000001, 0}, {0x969384cc85e4f376, 0x7483ab72c7895c74}},
    {13, {0x243f6a8885a308d3, 0x13198a2e03707344}, {1, 0}, {0xf76fab3d0c8c5f58, 0x86a6582b195612d5}},
    {13, {0x452821e638d01377, 0xbe5466cf34e90c6c}, {0, 0x8000000000000000}, {0xc74c1599c6d82c7f, 0x7d40926bdb8a9b86}},
    {13, {0, 0xffffffffffffffff}, {0, 0xffffffffffffffff}, {0xb05f97bf8112bd85, 0x1e2febcdf6f2434b}},
    {20, {0x0000000000000001, 0}, {0x0000000000000001, 0}, {0x76f8c465410f1b27, 0xd44c2d67df04a330}},
    {20, {0x243f6a8885a308d3, 0x13198a2e03707344}, {0, 1}, {0x99cec910eff5ec80, 0x590c31d2679b536f}},
    {20, {0xa4093822299f31d0, 0x082efa98ec4e6c89}, {0, 0xffffffffffffffff}, {0x69f5517074ffb421, 0x364c6cb5114df09b}},
    {20, {0x452821e638d01377, 0xbe5466cf34e90c6c}, {0, 0x8000000000000000}, {0x89983220cc01af30, 0x756813c51f68660f}},
    // Random123's tests/kat_vectors, the all-zero rows (as quoted in the randii OCaml port's kat test).
    {13, {0, 0}, {0, 0}, {0xf167b032c3b480bd, 0xe91f9fee4b7a6fb5}},
    {20, {0, 0}, {0, 0}, {0xc2b6e3a8c2c69865, 0x6f81ed42f350084d}},
};

template <int R>
std::array<std::uint64_t, 2> philox(const PhiloxRow& t) {
  Philox4x32<R> g;
  g.rounds = t.rounds;
  return g.hash(t.ctr[0], t.ctr[1], t.ctr[2], t.ctr[3], t.key[0], t.key[1]);
}

TEST(KatRandom123, Philox4x32KatVectors) {
  for (const auto& t : kPhilox) {
    const std::array<std::uint64_t, 2> want{join32(t.expect[1], t.expect[0]), join32(t.expect[3], t.expect[2])};
    EXPECT_EQ(philox<0>(t), want) << "runtime rounds " << t.rounds;
    EXPECT_EQ(t.rounds == 7 ? philox<7>(t) : philox<10>(t), want) << "compile-time rounds " << t.rounds;
  }
}

template <int R>
std::array<std::uint64_t, 2> threefry(const ThreefryRow& t) {
  Threefry2x64<R> g;
  g.rounds = t.rounds;
  return g.hash(t.ctr[0], t.ctr[1], t.key[0], t.key[1]);
}

TEST(KatRandom123, Threefry2x64KatVectors) {
  for (const auto& t : kThreefry) {
    EXPECT_EQ(threefry<0>(t), t.expect) << "runtime rounds " << t.rounds;
    EXPECT_EQ(t.rounds == 13 ? threefry<13>(t) : threefry<20>(t), t.expect) << "compile-time rounds " << t.rounds;
  }
}

// Our counter, distance and pair-step layouts against Random123's own C++ functors at random inputs.
TEST(KatRandom123, WrappersMatchRandom123Functors) {
  std::mt19937_64 pick(20240611);
  r123::Philox4x32_R<10> philox_ref;
  r123::Threefry2x64_R<20> threefry_ref;
  for (int n = 0; n < 1000; ++n) {
    Philox4x32<10> p;
    Threefry2x64<20> t;
    for (auto& k : p.key) k = static_cast<std::uint32_t>(pick());
    t.key = p.key;
    const std::uint64_t start = pick(), i = pick() % 1000000, step = pick(), seed = pick();
    const std::uint32_t a = static_cast<std::uint32_t>(pick()), b = static_cast<std::uint32_t>(pick());
    const double dx = std::ldexp(static_cast<double>(pick() >> 11), -53) - 0.5, dy = -0.25 * dx;

    const auto c = start + i;
    auto pr = philox_ref({{lo32(c), hi32(c), 0, 0}}, {{p.key[0], p.key[1]}});
    EXPECT_EQ(p.stream(start, i)[0], join32(pr.v[1], pr.v[0]));
    EXPECT_EQ(p.stream(start, i)[1], join32(pr.v[3], pr.v[2]));
    const auto xb = std::bit_cast<std::uint64_t>(dx), yb = std::bit_cast<std::uint64_t>(dy);
    pr = philox_ref({{lo32(xb), hi32(xb), lo32(yb), hi32(yb)}}, {{p.key[0], p.key[1]}});
    EXPECT_EQ(p.distance(dx, dy, 0.0)[1], join32(pr.v[3], pr.v[2]));
    pr = philox_ref({{a, b, lo32(step), hi32(step)}}, {{p.key[0] ^ lo32(seed), p.key[1] ^ hi32(seed)}});
    EXPECT_EQ(p.pair_step(a, b, step, seed)[0], join32(pr.v[1], pr.v[0]));

    const std::uint64_t k0 = join32(t.key[1], t.key[0]), k1 = join32(t.key[3], t.key[2]);
    auto tr = threefry_ref({{c, 0}}, {{k0, k1}});
    EXPECT_EQ(t.stream(start, i)[0], tr.v[0]);
    EXPECT_EQ(t.stream(start, i)[1], tr.v[1]);
    tr = threefry_ref({{xb, yb}}, {{k0, k1}});
    EXPECT_EQ(t.distance(dx, dy, 0.0)[0], tr.v[0]);
    tr = threefry_ref({{join32(b, a), step}}, {{k0 ^ seed, k1}});
    EXPECT_EQ(t.pair_step(a, b, step, seed)[1], tr.v[1]);
  }
}

// ---- SplitMix64 ---------------------------------------------------------------------------------------------
// Vigna's splitmix64.c seeded with 1234567: the first five outputs (Rosetta Code, "Pseudo-random
// numbers/Splitmix64", which shows them from the reference implementation).
TEST(KatSplitMix64, SeedFromTheReferenceImplementation) {
  constexpr std::uint64_t kExpect[] = {6457827717110365317ull, 3203168211198807973ull, 9817491932198370423ull,
                                       4593380528125082431ull, 16408922859458223821ull};
  const SplitMix64 g;
  for (std::uint64_t i = 0; i < 5; ++i) EXPECT_EQ(g.stream(1234567, i)[0], kExpect[i]) << "output " << i;
}

// ---- MT19937 ------------------------------------------------------------------------------------------------
// C++ standard [rand.predef]: the 10000th consecutive output of a default-constructed std::mt19937 is 4123659995.
TEST(KatMt19937, TenThousandthOutputOfTheStandard) {
  std::mt19937 mt;
  mt.discard(9999);
  EXPECT_EQ(mt(), 4123659995u);
  // Our wrapper's default seed is the standard's 5489, and a 64-bit word is two draws, high first.
  Mt19937 ours;
  std::mt19937 ref;
  const std::uint32_t hi = ref();
  EXPECT_EQ(ours.next64(), join32(hi, ref()));
}

// Our engine is std::mt19937's sequence: the standard's 10000th output, then, for several seeds, single draws,
// bulk fills of lengths that straddle the 624-word regeneration, discards, and 64-bit words in bulk.
TEST(KatMt19937, OwnEngineIsTheStandardsSequence) {
  Mt19937Engine first;
  first.discard(9999);
  EXPECT_EQ(first(), 4123659995u);
  for (const std::uint32_t seed : {5489u, 1u, 0u, 0xffffffffu, 20211012u}) {
    std::mt19937 ref(seed);
    Mt19937Engine ours(seed);
    for (int i = 0; i < 1500; ++i) ASSERT_EQ(ours(), ref()) << "seed " << seed << " draw " << i;
    std::vector<std::uint32_t> got;
    for (const std::size_t n : {1u, 7u, 623u, 624u, 625u, 1300u, 0u, 2u}) {
      got.assign(n, 0);
      ours.fill(got.data(), n);
      for (std::size_t t = 0; t < n; ++t) ASSERT_EQ(got[t], ref()) << "seed " << seed << " fill " << n;
    }
    ours.discard(1000), ref.discard(1000);
    EXPECT_EQ(ours(), ref());
  }
  Mt19937 bulk(77), one(77);
  std::vector<std::uint64_t> words(2000);
  bulk.fill64(words.data(), 3);
  bulk.fill64(words.data() + 3, words.size() - 3);
  for (std::size_t t = 0; t < words.size(); ++t) ASSERT_EQ(words[t], one.next64()) << t;
  // From an odd draw on (the pairs straddle each regeneration), in bulk and before tempering: temper64 of each
  // untempered word is the word.
  Mt19937 odd(78), odd_raw(78), odd_one(78);
  odd.engine(), odd_raw.engine(), odd_one.engine();
  std::vector<std::uint64_t> tempered(1500), raw(1500);
  odd.fill64(tempered.data(), tempered.size());
  odd_raw.fill64_untempered(raw.data(), raw.size());
  for (std::size_t t = 0; t < raw.size(); ++t) {
    const std::uint64_t w = odd_one.next64();
    ASSERT_EQ(tempered[t], w) << t;
    ASSERT_EQ(Mt19937::temper64(raw[t]), w) << t;
  }
}

// temper64, both halves tempered in whole-word operations, is the engine's 32-bit tempering of each half.
TEST(KatMt19937, WholeWordTemperingIsEachHalfs) {
  std::mt19937_64 pick(3);
  for (int k = 0; k < 100000; ++k) {
    const std::uint64_t w = pick();
    ASSERT_EQ(Mt19937::temper64(w), join32(Mt19937Engine::temper(hi32(w)), Mt19937Engine::temper(lo32(w)))) << w;
  }
}

// Matsumoto & Nishimura's init_by_array (mt19937ar.c, 2002), written from the published algorithm, to put the
// reference's seeding into a std::mt19937 through its textual state (the 624 words, [rand.eng.mers]).
std::array<std::uint32_t, 624> init_by_array(const std::vector<std::uint32_t>& key) {
  constexpr int n = 624;
  std::array<std::uint32_t, n> mt{};
  mt[0] = 19650218u;
  for (int i = 1; i < n; ++i) mt[i] = 1812433253u * (mt[i - 1] ^ (mt[i - 1] >> 30)) + static_cast<std::uint32_t>(i);
  int i = 1, j = 0;
  for (int k = std::max<int>(n, static_cast<int>(key.size())); k > 0; --k) {
    mt[i] = (mt[i] ^ ((mt[i - 1] ^ (mt[i - 1] >> 30)) * 1664525u)) + key[j] + static_cast<std::uint32_t>(j);
    if (++i >= n) mt[0] = mt[n - 1], i = 1;
    if (++j >= static_cast<int>(key.size())) j = 0;
  }
  for (int k = n - 1; k > 0; --k) {
    mt[i] = (mt[i] ^ ((mt[i - 1] ^ (mt[i - 1] >> 30)) * 1566083941u)) - static_cast<std::uint32_t>(i);
    if (++i >= n) mt[0] = mt[n - 1], i = 1;
  }
  mt[0] = 0x80000000u;
  return mt;
}

// mt19937ar.out, the reference's published output for init_by_array({0x123, 0x234, 0x345, 0x456}): first ten.
TEST(KatMt19937, ReferenceOutputForInitByArray) {
  std::string words;
  for (std::uint32_t w : init_by_array({0x123, 0x234, 0x345, 0x456})) words += std::to_string(w) + ' ';
  std::mt19937 mt;
  std::istringstream state(words);
  state >> mt;
  if (state.fail()) {  // libstdc++ also expects its position index after the words: 624 = "twist next"
    state = std::istringstream(words + "624");
    state >> mt;
  }
  ASSERT_FALSE(state.fail());
  constexpr std::uint32_t kExpect[] = {1067595299u, 955945823u,  477289528u,  4107218783u, 4228976476u,
                                       3344332714u, 3355579695u, 227628506u, 810200273u,  2591290167u};
  for (std::uint32_t e : kExpect) EXPECT_EQ(mt(), e);
}

// GSL's gsl_rng_mt19937 and std::mt19937 give the same sequence for the same (non-zero) 32-bit seed.
TEST(KatMt19937, GslAndStdAgree) {
  gsl_rng* r = gsl_rng_alloc(gsl_rng_mt19937);
  ASSERT_NE(r, nullptr);
  gsl_rng_set(r, 5489);
  std::mt19937 mt(5489);
  for (int i = 0; i < 2000; ++i) ASSERT_EQ(gsl_rng_get(r), mt()) << "draw " << i;
  gsl_rng_free(r);
}

}  // namespace

}  // namespace dpdrng_test::rng_test_kat
