// pair_style dpd/hash (pair_dpd_hash.h says what it computes and how it is called).
#include "pair_dpd_hash.h"

#include <algorithm>
#include <cerrno>
#include <cinttypes>
#include <cmath>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string_view>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

#include "dpdrng/rng/dispatch.hpp"

using namespace LAMMPS_NS;
namespace rng = dpdrng::rng;

// The pair loop behind a virtual call: one instantiation of eval per noise type, chosen once in settings().
struct PairDPDHash::Kernel {
  virtual ~Kernel() = default;
  virtual void run(PairDPDHash &pair, int ifrom, int ito, double **f, const Tally &tally, std::FILE *zf) const = 0;
};

namespace dpd_hash {

// Coinciding beads (r = 0) have no direction: the pair is skipped, as pair_style dpd does.
constexpr double kMinDistance = 1.0e-10;

template <class Noise>
struct KernelOf final : PairDPDHash::Kernel {
  explicit KernelOf(Noise n) : noise(std::move(n)) {}
  void run(PairDPDHash &pair, int ifrom, int ito, double **f, const PairDPDHash::Tally &tally,
           std::FILE *zf) const override {
    pair.eval(noise, ifrom, ito, f, tally, zf);
  }
  Noise noise;
};

// The minimum image of one component on a periodic orthogonal axis. Applied to the owners' coordinates in the
// canonical (lower tag first) order, it is one expression on the same operands wherever the pair is evaluated.
inline double wrap(double d, bool periodic, double prd, double half) {
  if (!periodic) return d;
  if (d > half) return d - prd;
  if (d < -half) return d + prd;
  return d;
}

std::uint64_t parse_u64(const char *text, Error *error) {
  const std::string_view s(text);
  std::uint64_t value = 0;
  bool ok = !s.empty() && s.size() <= 20;
  for (char c : s) {
    if (c < '0' || c > '9') {
      ok = false;
      break;
    }
    const std::uint64_t digit = std::uint64_t(c - '0');
    if (value > (UINT64_MAX - digit) / 10) {
      ok = false;
      break;
    }
    value = value * 10 + digit;
  }
  if (!ok) error->all(FLERR, "pair_style dpd/hash: '{}' is not an integer in 0 .. 2^64-1", text);
  return value;
}

}  // namespace dpd_hash

PairDPDHash::PairDPDHash(LAMMPS *lmp) : Pair(lmp) {
  // No restart or data-file support: a run restarts from its input script and read_restart of the atoms.
  restartinfo = 0;
  single_enable = 1;
  comm_forward = 3;  // the owners' coordinates (canonical seeding)
}

PairDPDHash::~PairDPDHash() {
  release();
  memory->destroy(xowner);
}

void PairDPDHash::release() {
  if (!allocated) return;
  memory->destroy(setflag);
  memory->destroy(cutsq);
  memory->destroy(cut);
  memory->destroy(a0);
  memory->destroy(gamma);
  memory->destroy(sigma);
  allocated = 0;
}

void PairDPDHash::allocate() {
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  memory->create(cut, n + 1, n + 1, "pair:cut");
  memory->create(a0, n + 1, n + 1, "pair:a0");
  memory->create(gamma, n + 1, n + 1, "pair:gamma");
  memory->create(sigma, n + 1, n + 1, "pair:sigma");
  for (int i = 0; i <= n; i++)
    for (int j = 0; j <= n; j++) setflag[i][j] = 0, cut[i][j] = a0[i][j] = gamma[i][j] = sigma[i][j] = 0.0;
}

namespace dpd_hash {

// The serial style's tallies: Pair's own energy and virial sums.
struct PairTally final : PairDPDHash::Tally {
  explicit PairTally(PairDPDHash &p) : pair(p) {}
  void operator()(int i, int j, double evdwl, double fpair, double delx, double dely, double delz) const override {
    pair.tally(i, j, evdwl, fpair, delx, dely, delz);
  }
  PairDPDHash &pair;
};

}  // namespace dpd_hash

void PairDPDHash::tally(int i, int j, double evdwl, double fpair, double delx, double dely, double delz) {
  ev_tally(i, j, atom->nlocal, force->newton_pair, evdwl, 0.0, fpair, delx, dely, delz);
}

void PairDPDHash::compute(int eflag, int vflag) {
  ev_init(eflag, vflag);
  std::FILE *zf = prepare();
  run_kernel(0, list->inum, atom->f, dpd_hash::PairTally(*this), zf);
  if (zf) std::fclose(zf);
  if (vflag_fdotr) virial_fdotr_compute();
}

void PairDPDHash::run_kernel(int ifrom, int ito, double **f, const Tally &tally, std::FILE *zf) {
  kernel->run(*this, ifrom, ito, f, tally, zf);
}

std::FILE *PairDPDHash::prepare() {
  if (!kernel) error->all(FLERR, "pair_style dpd/hash: no noise set (pair_style arguments missing)");
  if (canonical) {
    // Every atom's owner coordinates, ghosts included: the ghosts' come from their owners by forward comm,
    // unshifted (a shifted and unshifted-back coordinate need not equal the owner's bits).
    if (atom->nmax > nmax_owner) {
      memory->destroy(xowner);
      nmax_owner = atom->nmax;
      memory->create(xowner, nmax_owner, 3, "pair:xowner");
    }
    double **x = atom->x;
    for (int i = 0; i < atom->nlocal; i++) xowner[i][0] = x[i][0], xowner[i][1] = x[i][1], xowner[i][2] = x[i][2];
    comm->forward_comm_pair(this);
  }
  if (zeta_file.empty() || zeta_written || update->ntimestep != zeta_step) return nullptr;
  const std::string name = zeta_file + "." + std::to_string(comm->me);
  std::FILE *zf = std::fopen(name.c_str(), "w");
  if (!zf) error->one(FLERR, "pair_style dpd/hash: cannot write {}: {}", name, std::strerror(errno));
  zeta_written = true;
  return zf;
}

template <class Noise>
void PairDPDHash::eval(const Noise &noise, int ifrom, int ito, double **f, const Tally &tally, std::FILE *zf) {
  double **x = atom->x, **v = atom->v;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal, newton_pair = force->newton_pair;
  const double *special_lj = force->special_lj;
  const double dtinvsqrt = 1.0 / std::sqrt(update->dt);
  const auto step = std::uint64_t(update->ntimestep);
  const bool px = domain->xperiodic, py = domain->yperiodic, pz = domain->zperiodic;
  const double lx = domain->xprd, ly = domain->yprd, lz = domain->zprd;
  const double hx = domain->xprd_half, hy = domain->yprd_half, hz = domain->zprd_half;

  const int *ilist = list->ilist, *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  for (int ii = ifrom; ii < ito; ii++) {
    const int i = ilist[ii];
    const double xi = x[i][0], yi = x[i][1], zi = x[i][2];
    const double vxi = v[i][0], vyi = v[i][1], vzi = v[i][2];
    const int itype = type[i];
    const int *jlist = firstneigh[i];
    const int jnum = numneigh[i];
    for (int jj = 0; jj < jnum; jj++) {
      int j = jlist[jj];
      const double factor_dpd = special_lj[sbmask(j)];
      j &= NEIGHMASK;
      const double delx = xi - x[j][0], dely = yi - x[j][1], delz = zi - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const int jtype = type[j];
      if (rsq >= cutsq[itype][jtype]) continue;
      const double r = std::sqrt(rsq);
      if (r < dpd_hash::kMinDistance) continue;

      // The pair in canonical order (lower tag first, separation from it to the other), so that either owner
      // of the pair, on any rank, hashes the same input.
      const bool i_first = tag[i] < tag[j];
      const int lo = i_first ? i : j, hi = i_first ? j : i;
      rng::PairInput in{std::uint32_t(tag[lo]), std::uint32_t(tag[hi]), 0.0, 0.0, 0.0, step};
      if constexpr (Noise::kSeeding == rng::Seeding::distance) {
        if (canonical) {
          in.dx = dpd_hash::wrap(xowner[hi][0] - xowner[lo][0], px, lx, hx);
          in.dy = dpd_hash::wrap(xowner[hi][1] - xowner[lo][1], py, ly, hy);
          in.dz = dpd_hash::wrap(xowner[hi][2] - xowner[lo][2], pz, lz, hz);
        } else {
          // r_j − r_i is −del exactly (IEEE subtraction is antisymmetric), turned round when j has the lower tag.
          const double s = i_first ? -1.0 : 1.0;
          in.dx = s * delx, in.dy = s * dely, in.dz = s * delz;
        }
      }
      const double zeta = noise(in);
      if (zf) {
        std::uint64_t bits;
        std::memcpy(&bits, &zeta, sizeof bits);
        std::fprintf(zf, "%" PRIu32 " %" PRIu32 " %d %016" PRIx64 "\n", in.i, in.j, int(j >= nlocal), bits);
      }

      // Groot & Warren (1997): F_ij = [a w − γ w² (e_ij·v_ij) + σ w ζ_ij / √Δt] e_ij, w = 1 − r/r_c, σ² = 2γk_BT.
      const double rinv = 1.0 / r;
      const double dot = delx * (vxi - v[j][0]) + dely * (vyi - v[j][1]) + delz * (vzi - v[j][2]);
      const double w = 1.0 - r / cut[itype][jtype];
      double fpair = a0[itype][jtype] * w;
      fpair -= gamma[itype][jtype] * w * w * dot * rinv;
      fpair += sigma[itype][jtype] * w * zeta * dtinvsqrt;
      fpair *= factor_dpd * rinv;
      f[i][0] += delx * fpair, f[i][1] += dely * fpair, f[i][2] += delz * fpair;
      if (newton_pair || j < nlocal) f[j][0] -= delx * fpair, f[j][1] -= dely * fpair, f[j][2] -= delz * fpair;
      if (evflag) {
        const double evdwl = eflag_either ? 0.5 * a0[itype][jtype] * cut[itype][jtype] * w * w * factor_dpd : 0.0;
        tally(i, j, evdwl, fpair, delx, dely, delz);
      }
    }
  }
}

void PairDPDHash::settings(int narg, char **arg) {
  constexpr const char *usage =
      "pair_style dpd/hash T cutoff generator rounds seeding distribution feed seed [key k0 k1 k2 k3] "
      "[zeta FILE STEP]";
  if (narg < 8) error->all(FLERR, "pair_style dpd/hash: {} arguments, expected at least 8: {}", narg, usage);
  temperature = utils::numeric(FLERR, arg[0], false, lmp);
  cut_global = utils::numeric(FLERR, arg[1], false, lmp);
  if (!(temperature >= 0.0)) error->all(FLERR, "pair_style dpd/hash: temperature {} is negative", arg[0]);
  if (!(cut_global > 0.0)) error->all(FLERR, "pair_style dpd/hash: cutoff {} is not positive", arg[1]);
  rng::GeneratorSpec spec;
  spec.name = arg[2];
  spec.rounds = utils::inumeric(FLERR, arg[3], false, lmp);
  if (spec.rounds < 0) error->all(FLERR, "pair_style dpd/hash: rounds {} is negative (0: the default)", arg[3]);
  const std::string seeding_name = arg[4];
  canonical = seeding_name == "canonical";
  const std::uint64_t seed = dpd_hash::parse_u64(arg[7], error);

  zeta_file.clear();
  zeta_step = -1;
  zeta_written = false;
  bool key_given = false;
  for (int k = 8; k < narg;) {
    const std::string word = arg[k];
    if (word == "key") {
      if (k + 5 > narg) error->all(FLERR, "pair_style dpd/hash: key needs four 32-bit words");
      for (int w = 0; w < 4; ++w) {
        const std::uint64_t kw = dpd_hash::parse_u64(arg[k + 1 + w], error);
        if (kw > UINT32_MAX) error->all(FLERR, "pair_style dpd/hash: key word {} exceeds 2^32-1", arg[k + 1 + w]);
        spec.key[std::size_t(w)] = std::uint32_t(kw);
      }
      key_given = true;
      k += 5;
    } else if (word == "zeta") {
      if (k + 3 > narg) error->all(FLERR, "pair_style dpd/hash: zeta needs a file name and a time step");
      zeta_file = arg[k + 1];
      zeta_step = utils::bnumeric(FLERR, arg[k + 2], false, lmp);
      if (zeta_step < 0) error->all(FLERR, "pair_style dpd/hash: zeta step {} is negative", arg[k + 2]);
      k += 3;
    } else {
      error->all(FLERR, "pair_style dpd/hash: unknown keyword '{}': {}", word, usage);
    }
  }

  std::string described;
  try {
    // dpdrng's pair seedings, and canonical: distance seeding on the owners' coordinates.
    if (seeding_name != "pair-step" && seeding_name != "distance" && !canonical)
      throw std::invalid_argument("unknown seeding '" + seeding_name + "' (known: pair-step, distance, canonical)");
    const rng::Seeding seeding = canonical ? rng::Seeding::distance : rng::parse_seeding(seeding_name);
    const rng::Distribution dist = rng::parse_distribution(arg[5]);
    const rng::Feed feed = rng::parse_feed(arg[6]);
    spec = rng::validated(spec);
    if (key_given && !rng::find_generator(spec.name).takes_key)
      throw std::invalid_argument("key: " + spec.name + " takes no key (the key words would change nothing)");
    rng::with_pair_noise(
        spec, seeding, dist, seed,
        [&](auto noise) {
          kernel = std::make_unique<dpd_hash::KernelOf<decltype(noise)>>(std::move(noise));
        },
        feed);
    described = rng::describe(spec);
  } catch (const std::exception &e) {
    error->all(FLERR, "pair_style dpd/hash: {}", e.what());
  }
  if (comm->me == 0) {
    utils::logmesg(lmp, "pair_style dpd/hash: noise {}, {} seeding, {} distribution, feed {}, seed {}\n",
                   described, seeding_name, arg[5], arg[6], seed);
    if (seeding_name == "distance")
      error->warning(FLERR, "pair_style dpd/hash: distance seeding hashes the separation as each rank computes "
                            "it, from shifted ghost coordinates: two ranks may draw different numbers for one "
                            "pair (canonical seeding does not)");
  }

  if (allocated)
    for (int i = 1; i <= atom->ntypes; i++)
      for (int j = i; j <= atom->ntypes; j++)
        if (setflag[i][j]) cut[i][j] = cut_global;
}

void PairDPDHash::coeff(int narg, char **arg) {
  if (narg < 4 || narg > 5)
    error->all(FLERR, "pair_coeff for dpd/hash: expected I J a gamma [cutoff], got {} arguments", narg);
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const double a_one = utils::numeric(FLERR, arg[2], false, lmp);
  const double gamma_one = utils::numeric(FLERR, arg[3], false, lmp);
  const double cut_one = narg == 5 ? utils::numeric(FLERR, arg[4], false, lmp) : cut_global;
  if (gamma_one < 0.0) error->all(FLERR, "pair_coeff for dpd/hash: gamma {} is negative", arg[3]);
  if (!(cut_one > 0.0)) error->all(FLERR, "pair_coeff for dpd/hash: cutoff {} is not positive", cut_one);
  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      a0[i][j] = a_one, gamma[i][j] = gamma_one, cut[i][j] = cut_one;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "pair_coeff for dpd/hash: no type pair in {} {}", arg[0], arg[1]);
}

void PairDPDHash::init_style() {
  if (!comm->ghost_velocity)
    error->all(FLERR, "pair_style dpd/hash needs the ghosts' velocities: comm_modify vel yes");
  if (canonical && domain->triclinic)
    error->all(FLERR, "pair_style dpd/hash: canonical seeding supports orthogonal boxes only");
  if (atom->natoms > bigint(UINT32_MAX))
    error->all(FLERR, "pair_style dpd/hash: the hashes take 32-bit atom tags; this system has {} atoms",
               atom->natoms);
  if (!atom->tag_enable) error->all(FLERR, "pair_style dpd/hash needs atom IDs (atom_modify id yes)");
  neighbor->request(this, instance_me);
}

double PairDPDHash::init_one(int i, int j) {
  if (setflag[i][j] == 0) error->all(FLERR, "pair_style dpd/hash: pair_coeff {} {} not set", i, j);
  sigma[i][j] = std::sqrt(2.0 * force->boltz * temperature * gamma[i][j]);
  cut[j][i] = cut[i][j], a0[j][i] = a0[i][j], gamma[j][i] = gamma[i][j], sigma[j][i] = sigma[i][j];
  return cut[i][j];
}

// The conservative part only (the energy and force of a configuration, as pair_style dpd's single()).
double PairDPDHash::single(int, int, int itype, int jtype, double rsq, double, double factor_dpd,
                           double &fforce) {
  const double r = std::sqrt(rsq);
  if (r < dpd_hash::kMinDistance) {
    fforce = 0.0;
    return 0.0;
  }
  const double w = 1.0 - r / cut[itype][jtype];
  fforce = a0[itype][jtype] * w * factor_dpd / r;
  return 0.5 * a0[itype][jtype] * cut[itype][jtype] * w * w * factor_dpd;
}

// The owners' coordinates travel unshifted: pbc_flag and pbc are ignored on purpose.
int PairDPDHash::pack_forward_comm(int n, int *list, double *buf, int, int *) {
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int i = list[k];
    buf[m++] = xowner[i][0], buf[m++] = xowner[i][1], buf[m++] = xowner[i][2];
  }
  return m;
}

void PairDPDHash::unpack_forward_comm(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; i++) xowner[i][0] = buf[m++], xowner[i][1] = buf[m++], xowner[i][2] = buf[m++];
}

double PairDPDHash::memory_usage() { return Pair::memory_usage() + 3.0 * sizeof(double) * nmax_owner; }
