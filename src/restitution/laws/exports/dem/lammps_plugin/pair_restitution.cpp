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

#include "fix_atom_contacts.h"
#include "modify.h"
#include "tsuji_contact.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using Restitution::RestitutionTable;

// The fix that keeps the pair's contacts on their atoms (fix_atom_contacts.h).
static const char *const STORE_ID = "RESTITUTION_CONTACTS_PAIR";

PairRestitution::PairRestitution(LAMMPS *lmp) :
    Pair(lmp), estar(nullptr), table_of(nullptr), contact_of(nullptr), store(nullptr),
    opened(0.0)
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
  // A new pair_style starts without contacts, as it did with the map of the first version.
  if (store && modify->get_fix_by_id(STORE_ID)) modify->delete_fix(STORE_ID);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(estar);
    memory->destroy(table_of);
    memory->destroy(contact_of);
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
  memory->create(contact_of, n, n, "pair:contact_of");
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) {
      setflag[i][j] = 0;
      table_of[i][j] = -1;
      contact_of[i][j] = -1;
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

  int table = -1, contact = -1;
  try {
    if (Restitution::ContactLaw::is_contact_file(arg[3])) {
      contact_laws.push_back(Restitution::ContactLaw::read(arg[3]));
      first_type.push_back(ilo);
      contact = static_cast<int>(contact_laws.size()) - 1;
    } else {
      tables.push_back(RestitutionTable::read(arg[3]));
      table = static_cast<int>(tables.size()) - 1;
    }
  } catch (const Restitution::TableError &err) {
    error->all(FLERR, "pair_coeff {} {}: {}", arg[0], arg[1], err.what());
  }
  if (contact >= 0) {
    const Restitution::ContactLaw &law = contact_laws[contact];
    if (!law.is_pair())
      error->all(FLERR, "pair_coeff {} {}: {} is a law of a grain on the wall (fix "
                 "wall/restitution), not of two grains", arg[0], arg[1], arg[3]);
    if (law.materials() == 2 && !(ilo == ihi && jlo == jhi && ilo < jlo))
      error->all(FLERR, "pair_coeff {} {}: {} holds two materials, the first type i's and the "
                 "second type j's: give it for one pair of types i < j", arg[0], arg[1], arg[3]);
  }

  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = (jlo > i ? jlo : i); j <= jhi; j++) {
      estar[i][j] = e;
      table_of[i][j] = table;
      contact_of[i][j] = contact;
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
  if (strcmp(update->unit_style, "si") != 0)
    error->all(FLERR, "pair restitution reads speeds in m/s and E* in Pa: use 'units si'");
  if (atom->natoms >= (bigint(1) << 32))
    error->all(FLERR, "pair restitution keys contacts by atom IDs below 2^32");

  // A newton-off list whatever the newton setting: each rank meets every contact of the atoms
  // it owns and keeps its state on them, so a contact's state never depends on which rank
  // computed it before (with newton on only one of two ranks would see it).
  neighbor->add_request(this, NeighConst::REQ_SIZE | NeighConst::REQ_NEWTON_OFF);
  if (!store) {
    Fix *fix = modify->get_fix_by_id(STORE_ID);
    if (!fix) fix = modify->add_fix(std::string(STORE_ID) + " all RESTITUTION_CONTACTS");
    store = dynamic_cast<FixAtomContacts *>(fix);
    if (!store) error->all(FLERR, "pair restitution: fix {} is not its contact store", STORE_ID);
  }

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
  contact_of[hi][lo] = contact_of[lo][hi];
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

  const int inum = list->inum;
  const int *ilist = list->ilist, *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;

  Restitution::AtomContacts &contacts = store->contacts;
  contacts.begin();
  pushes.clear();
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

      // The contact's state on each atom this rank owns; a ghost's owner keeps its own copy,
      // fixed from the same positions and velocities at the first touch.
      const bool jlocal = j < nlocal;
      Restitution::ContactState *state = contacts.find(i, tag[j]);
      Restitution::ContactState *mirror = jlocal ? contacts.find(j, tag[i]) : nullptr;
      if (!state && mirror) {
        state = contacts.open(i, tag[j], mirror->w, mirror->epsilon, mirror->beta);
      } else if (!state) {
        const double w = std::fabs(vn);
        double eps = 0.0, beta = 0.0;
        try {
          const int law = contact_of[itype][jtype];
          if (law >= 0) {
            // The contact's own radii and masses; which material is whose by the types.
            const Restitution::ContactLaw &contact = contact_laws[law];
            const int mi = contact.materials() == 2 && itype != first_type[law] ? 1 : 0;
            const int mj = contact.materials() == 2 ? 1 - mi : 0;
            eps = contact.pair(w, estar[itype][jtype], radius[i], rmass[i], mi, radius[j],
                               rmass[j], mj).epsilon;
            beta = contact.beta(eps);
          } else {
            beta = tables[table_of[itype][jtype]].first_touch(w, eps);
          }
        } catch (const Restitution::TableError &err) {
          error->one(FLERR, "pair restitution, atoms {} and {} (types {} {}): {}", tag[i],
                     tag[j], itype, jtype, err.what());
        }
        state = contacts.open(i, tag[j], w, eps, beta);
        // Counted once over all ranks: by the owner of the atom with the lower ID.
        if (tag[i] < tag[j] || jlocal) opened += 1.0;
      }
      if (jlocal && !mirror) contacts.open(j, tag[i], state->w, state->epsilon, state->beta);

      const double rstar = radius[i] * radius[j] / radsum;
      const double mstar = rmass[i] * rmass[j] / (rmass[i] + rmass[j]);
      double energy;
      const double fn = Restitution::tsuji_normal_force(estar[itype][jtype], rstar, mstar,
                                                        state->beta, radsum - r, -vn, energy);
      const double fx = fn * nx, fy = fn * ny, fz = fn * nz;
      pushes.push_back(Push{i, static_cast<std::int64_t>(tag[j]), {fx, fy, fz}});
      if (jlocal) pushes.push_back(Push{j, static_cast<std::int64_t>(tag[i]), {-fx, -fy, -fz}});
      if (evflag) ev_tally_xyz(i, j, nlocal, 0, energy, 0.0, fx, fy, fz, dx, dy, dz);
    }
  }
  // Each atom's forces summed in the order of its partners' IDs, not of the neighbor list
  // (which depends on how the box is cut into ranks): the same sum, bit for bit, on any number
  // of ranks. The force of one contact is the same bits seen from either atom (dx, vn and the
  // reduced radius and mass are symmetric), so both owners agree.
  std::sort(pushes.begin(), pushes.end(), [](const Push &a, const Push &b) {
    if (a.atom != b.atom) return a.atom < b.atom;
    if (a.partner != b.partner) return a.partner < b.partner;
    return std::lexicographical_compare(a.f, a.f + 3, b.f, b.f + 3);
  });
  for (const Push &p : pushes) {
    f[p.atom][0] += p.f[0];
    f[p.atom][1] += p.f[1];
    f[p.atom][2] += p.f[2];
  }
  contacts.sweep(nlocal);
  pvector[0] = contacts.count(nlocal, tag, true);
  pvector[1] = opened;
}
