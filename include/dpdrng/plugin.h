/* dpdrng/plugin.h: the C interface through which a user's own keyed hash runs wherever dpdrng names a
 * generator (`ext:PATH` in gen, simulate, decompose, bench and study configs).
 *
 * A plug-in is a shared library that exports one function, dpdrng_plugin_get(), returning a pointer to a
 * dpdrng_plugin that stays valid while the library is loaded. dpdrng refuses a library whose `abi` differs from
 * the DPDRNG_PLUGIN_ABI it was built with, whose `words` is neither 1 nor 2, or that supports no seeding.
 *
 * Contract of every entry:
 *  - A pure function of its arguments: no global state, no locks, no allocation needed. dpdrng calls it from
 *    several threads at once and in batches whose size n it chooses (a row's or a cell layer's pairs); the
 *    result for an input must not depend on n, on the batch an input falls in, or on the calling thread.
 *  - It fills out[0 .. n*words): the block of input k in out[k*words .. (k+1)*words), word 0 first.
 *  - A NULL entry means that seeding is not supported; dpdrng says so when a run asks for it.
 *
 * Seedings (the same as for the built-in generators):
 *  - counter(start, n, out): block k is the hash of the counter start + k (`gen`'s streams; the counter wraps
 *    modulo 2^64 inside the plug-in, dpdrng never asks past 2^64 - 1).
 *  - pair_step(i, j, step, seed, n, out): block k keys pair (i[k], j[k]), always i[k] < j[k], at time step `step`
 *    under the user's 64-bit seed.
 *  - distance(dx, dy, dz, n, out): block k keys the separation r_j - r_i of a pair i < j (minimum image), as
 *    IEEE-754 doubles; the two owners of a pair see bitwise the same separation.
 *  Under the `blocks` Box-Muller feed dpdrng asks for a pair's second block itself: pair_step with the step
 *  complemented (~step), distance with the components rotated (dy, dz, dx). A plug-in does nothing for it.
 *
 * What dpdrng does with the words: the Gaussian noise under the `halves` feed reads the two 32-bit halves of
 * word 0 (low half first); under `blocks` and `inverse`, and for uniform noise, the top 53 bits of word 0; with
 * words = 2 the `halves` feed reads the top 53 bits of words 0 and 1. `dpdrng gen -g ext:PATH` writes every word.
 *
 * C99; no dpdrng library needs to be linked. The struct's layout is the ABI: fields are only ever appended under
 * a new DPDRNG_PLUGIN_ABI value.
 */
#ifndef DPDRNG_PLUGIN_H
#define DPDRNG_PLUGIN_H

#include <stddef.h>
#include <stdint.h>

#define DPDRNG_PLUGIN_ABI 1

#ifdef __cplusplus
extern "C" {
#endif

typedef struct dpdrng_plugin {
  uint32_t abi;     /* DPDRNG_PLUGIN_ABI */
  const char *name; /* a short name for reports, e.g. "tea32c(1)" */
  uint32_t words;   /* 64-bit words per block: 1 or 2 */
  void (*counter)(uint64_t start, size_t n, uint64_t *out);
  void (*pair_step)(const uint32_t *i, const uint32_t *j, uint64_t step, uint64_t seed, size_t n, uint64_t *out);
  void (*distance)(const double *dx, const double *dy, const double *dz, size_t n, uint64_t *out);
} dpdrng_plugin;

/* The one symbol a plug-in exports. */
const dpdrng_plugin *dpdrng_plugin_get(void);

#ifdef __cplusplus
}
#endif

#endif /* DPDRNG_PLUGIN_H */
