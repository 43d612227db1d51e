// pair_style dpd/hash: the DPD pair force of Groot & Warren (1997), as LAMMPS's pair_style dpd computes it, with
// the random number ζ_ij of each pair taken from a keyed hash of the pair (dpdrng::rng) instead of a per-rank
// stream. Both owners of a pair that straddles two ranks then draw the same ζ_ij without talking, so the force
// is antisymmetric with newton_pair off as well as on, and a run's noise does not depend on the rank count.
//
//   pair_style dpd/hash T rc generator rounds seeding distribution feed seed [key k0 k1 k2 k3] [zeta FILE STEP]
//
// generator: a dpdrng keyed hash (tea32, tea64, philox, ..., `dpdrng list`) or ext:PATH, a plug-in;
// rounds: a round count, or 0 for the generator's default; seeding: pair-step (global atom tags and the time
// step), distance (the bits of the pair's separation as this rank computes it: ghosts carry shifted coordinates,
// so two ranks may disagree), or canonical (the separation recomputed from both atoms' owner coordinates, which
// the style forwards to the ghosts: the same bits on every rank); distribution: gauss or uniform; feed: halves,
// blocks or inverse (how uniforms become a Gaussian); seed: the pair-step seed (any 64-bit integer).
// `zeta FILE STEP` writes, at time step STEP only, one line per pair this rank evaluates into FILE.<rank>:
// the two tags (lower first), whether the pair has a ghost, and ζ as its IEEE-754 bits: a check, not output.
// pair_style dpd/hash/omp (pair_dpd_hash_omp.h) runs the same pair loop on LAMMPS's OpenMP threads.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "pair.h"

namespace LAMMPS_NS {

class PairDPDHash : public Pair {
 public:
  explicit PairDPDHash(class LAMMPS *);
  ~PairDPDHash() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  double single(int, int, int, int, double, double, double, double &) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  double memory_usage() override;

  // Where the pair loop's energy and virial go on the steps that tally them: Pair's own sums, or one thread's
  // (the /omp variant). A virtual call per pair on those steps only.
  struct Tally {
    virtual ~Tally() = default;
    virtual void operator()(int i, int j, double evdwl, double fpair, double delx, double dely,
                            double delz) const = 0;
  };

  // The pair loop for one noise type (the generator, seeding and distribution as constants), over the entries
  // ifrom .. ito-1 of the neighbour list, into the force array f (LAMMPS's, or a thread's). Called after
  // ev_init() and prepare(); zf: the zeta check's file, or null.
  template <class Noise>
  void eval(const Noise &noise, int ifrom, int ito, double **f, const Tally &tally, std::FILE *zf);

  struct Kernel;
  // Pair's own energy and virial tally for one pair (the serial Tally).
  void tally(int i, int j, double evdwl, double fpair, double delx, double dely, double delz);

 protected:
  double temperature = 0.0, cut_global = 0.0;
  double **cut = nullptr, **a0 = nullptr, **gamma = nullptr, **sigma = nullptr;
  bool canonical = false;       // distance seeding on the owners' coordinates
  double **xowner = nullptr;    // canonical: each atom's coordinates as its owner holds them (ghosts too)
  int nmax_owner = 0;
  std::unique_ptr<Kernel> kernel;
  std::string zeta_file;        // the check's output, empty when not asked
  std::int64_t zeta_step = -1;
  bool zeta_written = false;

  void allocate();
  void release();
  // Before a force evaluation: the ghosts' owner coordinates (canonical seeding), and the zeta check's file when
  // this is its step (null otherwise; the caller closes it).
  std::FILE *prepare();
  void run_kernel(int ifrom, int ito, double **f, const Tally &tally, std::FILE *zf);
};

}  // namespace LAMMPS_NS
