// lmp_dpdrng: LAMMPS's command-line program with pair_style dpd/hash and its OPENMP variant dpd/hash/omp added to
// its pair styles. The styles are compiled apart from the LAMMPS library and entered into the library's style
// table before the input is read, so one LAMMPS build serves every version of them; `-sf omp` (or `suffix omp`)
// finds the variant there by its name.
#include <mpi.h>

#include "force.h"
#include "input.h"
#include "lammps.h"
#include "pair_dpd_hash.h"
#include "pair_dpd_hash_omp.h"

namespace {
LAMMPS_NS::Pair *create_dpd_hash(LAMMPS_NS::LAMMPS *lmp) { return new LAMMPS_NS::PairDPDHash(lmp); }
LAMMPS_NS::Pair *create_dpd_hash_omp(LAMMPS_NS::LAMMPS *lmp) { return new LAMMPS_NS::PairDPDHashOMP(lmp); }
}  // namespace

int main(int argc, char **argv) {
  MPI_Init(&argc, &argv);
  auto *lmp = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
  (*lmp->force->pair_map)["dpd/hash"] = &create_dpd_hash;
  (*lmp->force->pair_map)["dpd/hash/omp"] = &create_dpd_hash_omp;
  lmp->input->file();
  delete lmp;
  MPI_Finalize();
  return 0;
}
