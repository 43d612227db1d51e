// pair_style dpd/hash/omp (pair_dpd_hash_omp.h says how it shares the work and what stays bitwise).
#include "pair_dpd_hash_omp.h"

#include "atom.h"
#include "comm.h"
#include "force.h"
#include "neigh_list.h"
#include "suffix.h"
#include "timer.h"

using namespace LAMMPS_NS;

namespace {

// The tallies of one thread, into its ThrData.
struct ThreadTally final : PairDPDHash::Tally {
  ThreadTally(PairDPDHashOMP &p, ThrData *t) : pair(p), thr(t) {}
  void operator()(int i, int j, double evdwl, double fpair, double delx, double dely, double delz) const override {
    pair.tally_thr(i, j, evdwl, fpair, delx, dely, delz, thr);
  }
  PairDPDHashOMP &pair;
  ThrData *thr;
};

}  // namespace

PairDPDHashOMP::PairDPDHashOMP(LAMMPS *lmp) : PairDPDHash(lmp), ThrOMP(lmp, THR_PAIR) {
  suffix_flag |= Suffix::OMP;
  respa_enable = 0;
}

void PairDPDHashOMP::tally_thr(int i, int j, double evdwl, double fpair, double delx, double dely, double delz,
                               ThrData *thr) {
  ev_tally_thr(this, i, j, atom->nlocal, force->newton_pair, evdwl, 0.0, fpair, delx, dely, delz, thr);
}

void PairDPDHashOMP::compute(int eflag, int vflag) {
  ev_init(eflag, vflag);
  // The owners' coordinates travel by MPI and the zeta file is opened before the threads start: neither may
  // happen inside the parallel region.
  std::FILE *zf = prepare();
  const int nall = atom->nlocal + atom->nghost, inum = list->inum, nthreads = comm->nthreads;
#if defined(_OPENMP)
#pragma omp parallel default(shared)
#endif
  {
    int ifrom, ito, tid;
    loop_setup_thr(ifrom, ito, tid, inum, nthreads);
    ThrData *thr = fix->get_thr(tid);
    thr->timer(Timer::START);
    ev_setup_thr(eflag, vflag, nall, eatom, vatom, nullptr, thr);
    // Lines of the zeta check from several threads interleave whole: stdio locks the stream for each call.
    run_kernel(ifrom, ito, thr->get_f(), ThreadTally(*this, thr), zf);
    thr->timer(Timer::PAIR);
    reduce_thr(this, eflag, vflag, thr);
  }
  if (zf) std::fclose(zf);
}

double PairDPDHashOMP::memory_usage() { return memory_usage_thr() + PairDPDHash::memory_usage(); }
