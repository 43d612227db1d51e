/* Plug-ins that dpdrng must refuse, one defect per build (PLUGIN_DEFECT): a foreign ABI, an unsupported word
 * count, no entry at all, no name, a NULL struct, and one without distance seeding (valid, but refused under it). */
#include <dpdrng/plugin.h>

static void counter(uint64_t start, size_t n, uint64_t *out) {
  for (size_t k = 0; k < n; ++k) out[k] = (start + k) * 0x9e3779b97f4a7c15ULL;
}
static void pair_step(const uint32_t *i, const uint32_t *j, uint64_t step, uint64_t seed, size_t n, uint64_t *out) {
  for (size_t k = 0; k < n; ++k) out[k] = (((uint64_t)j[k] << 32 | i[k]) ^ step ^ seed) * 0x9e3779b97f4a7c15ULL;
}

#if PLUGIN_DEFECT == 1
static const dpdrng_plugin kPlugin = {DPDRNG_PLUGIN_ABI + 1, "abi", 1, counter, pair_step, 0};
#elif PLUGIN_DEFECT == 2
static const dpdrng_plugin kPlugin = {DPDRNG_PLUGIN_ABI, "words", 3, counter, pair_step, 0};
#elif PLUGIN_DEFECT == 3
static const dpdrng_plugin kPlugin = {DPDRNG_PLUGIN_ABI, "entries", 1, 0, 0, 0};
#elif PLUGIN_DEFECT == 4
static const dpdrng_plugin kPlugin = {DPDRNG_PLUGIN_ABI, "", 1, counter, pair_step, 0};
#elif PLUGIN_DEFECT == 6
static const dpdrng_plugin kPlugin = {DPDRNG_PLUGIN_ABI, "no-distance", 1, counter, pair_step, 0};
#endif

#if PLUGIN_DEFECT == 5
const dpdrng_plugin *dpdrng_plugin_get(void) { return 0; }
#else
const dpdrng_plugin *dpdrng_plugin_get(void) { return &kPlugin; }
#endif
