/* A two-word plug-in around a hash dpdrng does not have: the 64-bit finaliser of Appleby's MurmurHash3 (public
 * domain), fmix64, applied twice per block. It illustrates the ABI for words = 2 and how a user's hash enters
 * every seeding; it carries no published analysis as a DPD noise source, which is what dpdrng's tests are for.
 *
 * Build:  cmake -S examples/plugin_fmix64 -B build/plugin_fmix64 -DCMAKE_PREFIX_PATH=<dpdrng's prefix>
 *         cmake --build build/plugin_fmix64
 * Run:    dpdrng simulate -g ext:build/plugin_fmix64/libfmix64.so --compare mt19937 --steps 3000
 */
#include <dpdrng/plugin.h>
#include <string.h>

static uint64_t fmix64(uint64_t k) {
  k ^= k >> 33;
  k *= 0xff51afd7ed558ccdULL;
  k ^= k >> 33;
  k *= 0xc4ceb9fe1a85ec53ULL;
  k ^= k >> 33;
  return k;
}

/* Two words from two input words: the second input is mixed first so that (a, b) and (b, a) differ. */
static void block(uint64_t a, uint64_t b, uint64_t *out) {
  const uint64_t h = fmix64(b + 0x9e3779b97f4a7c15ULL);
  out[0] = fmix64(a ^ h);
  out[1] = fmix64(out[0] ^ (h + 0xd1b54a32d192ed03ULL));
}

static uint64_t bits(double x) {
  uint64_t u;
  memcpy(&u, &x, sizeof u);
  return u;
}

static void counter(uint64_t start, size_t n, uint64_t *out) {
  for (size_t k = 0; k < n; ++k) block(start + k, 0, out + 2 * k);
}

/* All three components of the separation: dx alone, then dy and dz folded into the second input. */
static void distance(const double *dx, const double *dy, const double *dz, size_t n, uint64_t *out) {
  for (size_t k = 0; k < n; ++k) block(bits(dx[k]), fmix64(bits(dy[k])) ^ bits(dz[k]), out + 2 * k);
}

static void pair_step(const uint32_t *i, const uint32_t *j, uint64_t step, uint64_t seed, size_t n, uint64_t *out) {
  const uint64_t s = step ^ fmix64(seed);
  for (size_t k = 0; k < n; ++k) block(((uint64_t)j[k] << 32) | i[k], s, out + 2 * k);
}

static const dpdrng_plugin kPlugin = {DPDRNG_PLUGIN_ABI, "fmix64x2", 2, counter, pair_step, distance};

const dpdrng_plugin *dpdrng_plugin_get(void) { return &kPlugin; }
