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

  // The pair loop for one noise type (the generator, seeding and distribution as constants).
  template <class Noise>
  void eval(const Noise &noise, int eflag, int vflag);

  struct Kernel;

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
};

}  // namespace LAMMPS_NS
