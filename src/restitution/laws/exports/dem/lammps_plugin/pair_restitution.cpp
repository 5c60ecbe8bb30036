// pair_style restitution (pair_restitution.h; physics in tsuji_contact.h).

#include "pair_restitution.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include "tsuji_contact.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using Restitution::RestitutionTable;

PairRestitution::PairRestitution(LAMMPS *lmp) : Pair(lmp), estar(nullptr), table_of(nullptr)
{
  single_enable = 0;
  restartinfo = 0;
  no_virial_fdotr_compute = 1;    // forces on ghost images come with their own tally
  finitecutflag = 1;
  nextra = 2;
  pvector = new double[nextra];
  pvector[0] = pvector[1] = 0.0;
}

PairRestitution::~PairRestitution()
{
  delete[] pvector;
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(estar);
    memory->destroy(table_of);
  }
}

void PairRestitution::allocate()
{
  allocated = 1;
  const int n = atom->ntypes + 1;
  memory->create(setflag, n, n, "pair:setflag");
  memory->create(cutsq, n, n, "pair:cutsq");
  memory->create(estar, n, n, "pair:estar");
  memory->create(table_of, n, n, "pair:table_of");
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) {
      setflag[i][j] = 0;
      table_of[i][j] = -1;
      estar[i][j] = 0.0;
    }
}

void PairRestitution::settings(int narg, char ** /*arg*/)
{
  if (narg != 0) error->all(FLERR, "pair_style restitution takes no arguments");
}

void PairRestitution::coeff(int narg, char **arg)
{
  if (narg != 4)
    error->all(FLERR, "pair_coeff for restitution: expected 'pair_coeff i j E* table_file'");
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const double e = utils::numeric(FLERR, arg[2], false, lmp);
  if (!(e > 0.0)) error->all(FLERR, "pair_coeff for restitution: E* must be > 0 Pa, got {}", e);

  try {
    tables.push_back(RestitutionTable::read(arg[3]));
  } catch (const Restitution::TableError &err) {
    error->all(FLERR, "pair_coeff {} {}: {}", arg[0], arg[1], err.what());
  }
  const int index = static_cast<int>(tables.size()) - 1;

  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = (jlo > i ? jlo : i); j <= jhi; j++) {
      estar[i][j] = e;
      table_of[i][j] = index;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "pair_coeff for restitution: no type pair i <= j given");
}

void PairRestitution::init_style()
{
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "pair restitution needs per-atom radius and mass: use atom_style sphere");
  if (!comm->ghost_velocity)
    error->all(FLERR, "pair restitution needs ghost velocities: add 'comm_modify vel yes'");
  if (comm->nprocs > 1)
    error->all(FLERR,
               "pair restitution keeps its per-contact state on one MPI rank; run on 1 rank "
               "(it has {})",
               comm->nprocs);
  if (strcmp(update->unit_style, "si") != 0)
    error->all(FLERR, "pair restitution reads speeds in m/s and E* in Pa: use 'units si'");
  if (atom->natoms >= (bigint(1) << 32))
    error->all(FLERR, "pair restitution keys contacts by atom IDs below 2^32");

  neighbor->add_request(this, NeighConst::REQ_SIZE);

  // The neighbor cutoff of a type pair: the sum of the two types' largest radii.
  const int n = atom->ntypes + 1;
  std::vector<double> local(n, 0.0);
  maxrad.assign(n, 0.0);
  for (int i = 0; i < atom->nlocal; i++)
    local[atom->type[i]] = std::fmax(local[atom->type[i]], atom->radius[i]);
  MPI_Allreduce(local.data(), maxrad.data(), n, MPI_DOUBLE, MPI_MAX, world);
}

double PairRestitution::init_one(int i, int j)
{
  const int lo = i < j ? i : j, hi = i < j ? j : i;
  if (!setflag[lo][hi])
    error->all(FLERR,
               "pair restitution has no pair_coeff for types {} {}: every type pair needs its "
               "own E* and table (no mixing)",
               lo, hi);
  estar[hi][lo] = estar[lo][hi];
  table_of[hi][lo] = table_of[lo][hi];
  return maxrad[i] + maxrad[j];
}

void PairRestitution::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  double **x = atom->x, **v = atom->v, **f = atom->f;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;

  const int inum = list->inum;
  const int *ilist = list->ilist, *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;

  contacts.begin();
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const int itype = type[i];
    const int *jlist = firstneigh[i];
    for (int jj = 0; jj < numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      const double rsq = dx * dx + dy * dy + dz * dz;
      const double radsum = radius[i] + radius[j];
      if (rsq >= radsum * radsum) continue;

      const int jtype = type[j];
      const double r = std::sqrt(rsq);
      if (r == 0.0)
        error->one(FLERR, "pair restitution: atoms {} and {} have the same centre", tag[i],
                   tag[j]);
      const double nx = dx / r, ny = dy / r, nz = dz / r;
      // Normal relative velocity of i away from j: < 0 approaching.
      const double vn = (v[i][0] - v[j][0]) * nx + (v[i][1] - v[j][1]) * ny +
          (v[i][2] - v[j][2]) * nz;

      Restitution::ContactState *state = contacts.find(tag[i], tag[j]);
      if (!state) {
        const RestitutionTable &table = tables[table_of[itype][jtype]];
        const double w = std::fabs(vn);
        double eps = 0.0, beta = 0.0;
        try {
          beta = table.first_touch(w, eps);
        } catch (const Restitution::TableError &err) {
          error->one(FLERR, "pair restitution, atoms {} and {} (types {} {}): {}", tag[i],
                     tag[j], itype, jtype, err.what());
        }
        state = contacts.open(tag[i], tag[j], w, eps, beta);
      }

      const double rstar = radius[i] * radius[j] / radsum;
      const double mstar = rmass[i] * rmass[j] / (rmass[i] + rmass[j]);
      double energy;
      const double fn = Restitution::tsuji_normal_force(estar[itype][jtype], rstar, mstar,
                                                        state->beta, radsum - r, -vn, energy);
      const double fx = fn * nx, fy = fn * ny, fz = fn * nz;
      f[i][0] += fx;
      f[i][1] += fy;
      f[i][2] += fz;
      if (newton_pair || j < nlocal) {
        f[j][0] -= fx;
        f[j][1] -= fy;
        f[j][2] -= fz;
      }
      if (evflag) ev_tally_xyz(i, j, nlocal, newton_pair, energy, 0.0, fx, fy, fz, dx, dy, dz);
    }
  }
  contacts.sweep();
  pvector[0] = static_cast<double>(contacts.live());
  pvector[1] = static_cast<double>(contacts.opened());
}
