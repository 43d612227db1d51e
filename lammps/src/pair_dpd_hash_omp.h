// pair_style dpd/hash/omp: pair_style dpd/hash with the pair loop shared among the OpenMP threads of LAMMPS's
// OPENMP package (`-sf omp`, or `suffix omp`, with `package omp N`). Each thread evaluates a contiguous slice
// of the neighbour list into a force array of its own, which the package then adds up.
//
// ζ_ij is a hash of the pair, not a draw from a per-thread stream, so every pair gets the same number whatever
// the thread count: a run's noise is the serial style's. The forces are the serial style's bit for bit on one
// thread; on several, an atom whose pairs fall in two threads' slices gets its force as the sum of two partial
// sums, added in another order than the serial loop's, so it may differ from the serial force in the last bits
// (docs/lammps.md has the measured size). The energy and virial are summed per thread in the same way.
#pragma once

#include "pair_dpd_hash.h"
#include "thr_omp.h"

namespace LAMMPS_NS {

class PairDPDHashOMP : public PairDPDHash, public ThrOMP {
 public:
  explicit PairDPDHashOMP(class LAMMPS *);
  void compute(int, int) override;
  double memory_usage() override;

  // One thread's energy and virial tally (ThrOMP's per-thread sums).
  void tally_thr(int i, int j, double evdwl, double fpair, double delx, double dely, double delz, ThrData *thr);
};

}  // namespace LAMMPS_NS
