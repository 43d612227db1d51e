// Compiled with the engine's include roots only (the `layering_enforced` test): it must fail to compile,
// because the engine does not link the statistics layer and so cannot see its headers.
#include "dpdrng/dpd/system.hpp"
#include "dpdrng/stats/summary.hpp"

double probe(std::span<const double> x) { return dpdrng::stats::median(x); }
