/* 32TEA(n) as a dpdrng plug-in, in plain scalar C: the words, the zeta and a simulation under it equal the
 * built-in `-g tea32 -r n` bit for bit (the test suite compares them). TEA is Wheeler & Needham's (1994) cipher
 * as Okada, Brumby & Yasuoka (2021) use it: the 64-bit seed split into x0 (low word) and x1 (high word), n
 * cycles under the key (3, 4, 5, 6), joined back as (x1 << 32) | x0.
 *
 * Build:  cmake -S examples/plugin_tea32 -B build/plugin_tea32 -DCMAKE_PREFIX_PATH=<dpdrng's prefix>
 *         cmake --build build/plugin_tea32          (-DTEA32_CYCLES=4 for 32TEA(4))
 * Run:    dpdrng gen -g ext:build/plugin_tea32/libtea32.so --count 4
 */
#include <dpdrng/plugin.h>
#include <string.h>

#ifndef TEA32_CYCLES
#define TEA32_CYCLES 1
#endif
#define TEA32_STR2(x) #x
#define TEA32_STR(x) TEA32_STR2(x)

static const uint32_t kKey[4] = {3, 4, 5, 6};

static uint64_t tea32(uint64_t seed, const uint32_t k[4]) {
  uint32_t x0 = (uint32_t)seed, x1 = (uint32_t)(seed >> 32), sum = 0;
  for (int r = 0; r < TEA32_CYCLES; ++r) {
    sum += 0x9E3779B9u;
    x0 += ((x1 << 4) + k[0]) ^ ((x1 >> 5) + k[1]) ^ (x1 + sum);
    x1 += ((x0 << 4) + k[2]) ^ ((x0 >> 5) + k[3]) ^ (x0 + sum);
  }
  return ((uint64_t)x1 << 32) | x0;
}

static void counter(uint64_t start, size_t n, uint64_t *out) {
  for (size_t k = 0; k < n; ++k) out[k] = tea32(start + k, kKey);
}

/* The paper's seeding: the IEEE-754 bits of the x component of the separation. */
static void distance(const double *dx, const double *dy, const double *dz, size_t n, uint64_t *out) {
  (void)dy;
  (void)dz;
  for (size_t k = 0; k < n; ++k) {
    uint64_t bits;
    memcpy(&bits, &dx[k], sizeof bits);
    out[k] = tea32(bits, kKey);
  }
}

/* One 64-bit block holds only the pair (j high, i low): the step and the seed go into the key. */
static void pair_step(const uint32_t *i, const uint32_t *j, uint64_t step, uint64_t seed, size_t n, uint64_t *out) {
  const uint32_t key[4] = {kKey[0] ^ (uint32_t)step, kKey[1] ^ (uint32_t)(step >> 32), kKey[2] ^ (uint32_t)seed,
                           kKey[3] ^ (uint32_t)(seed >> 32)};
  for (size_t k = 0; k < n; ++k) out[k] = tea32(((uint64_t)j[k] << 32) | i[k], key);
}

static const dpdrng_plugin kPlugin = {DPDRNG_PLUGIN_ABI, "tea32c(" TEA32_STR(TEA32_CYCLES) ")", 1, counter, pair_step,
                                      distance};

const dpdrng_plugin *dpdrng_plugin_get(void) { return &kPlugin; }
