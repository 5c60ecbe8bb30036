// fix wall/restitution (fix_wall_restitution.h; physics in tsuji_contact.h).

#include "fix_wall_restitution.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "update.h"

#include "tsuji_contact.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;
using Restitution::RestitutionTable;

FixWallRestitution::FixWallRestitution(LAMMPS *lmp, int narg, char **arg) :
    FixAtomContacts(lmp, narg, arg), per_contact(false), opened(0.0)
{
  if (narg != 7)
    error->all(FLERR,
               "fix wall/restitution: expected 'fix ID group wall/restitution E* table_file "
               "xplane|yplane|zplane coord'");
  estar = utils::numeric(FLERR, arg[3], false, lmp);
  if (!(estar > 0.0)) error->all(FLERR, "fix wall/restitution: E* must be > 0 Pa, got {}", estar);
  try {
    per_contact = Restitution::ContactLaw::is_contact_file(arg[4]);
    if (per_contact)
      contact = Restitution::ContactLaw::read(arg[4]);
    else
      table = RestitutionTable::read(arg[4]);
  } catch (const Restitution::TableError &err) {
    error->all(FLERR, "fix wall/restitution: {}", err.what());
  }
  if (per_contact && contact.is_pair())
    error->all(FLERR, "fix wall/restitution: {} is a law of two grains (pair_coeff), not of a "
               "grain on the wall", arg[4]);
  if (strcmp(arg[5], "xplane") == 0)
    axis = 0;
  else if (strcmp(arg[5], "yplane") == 0)
    axis = 1;
  else if (strcmp(arg[5], "zplane") == 0)
    axis = 2;
  else
    error->all(FLERR, "fix wall/restitution: the wall is xplane, yplane or zplane, got {}",
               arg[5]);
  coord = utils::numeric(FLERR, arg[6], false, lmp);

  vector_flag = 1;
  size_vector = 2;
  global_freq = 1;
  extvector = 0;
}

int FixWallRestitution::setmask()
{
  return POST_FORCE | FixAtomContacts::setmask();
}

void FixWallRestitution::init()
{
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "fix wall/restitution needs per-atom radius and mass: use atom_style sphere");
  if (strcmp(update->unit_style, "si") != 0)
    error->all(FLERR, "fix wall/restitution reads speeds in m/s and E* in Pa: use 'units si'");
  if (axis == 2 && domain->dimension == 2)
    error->all(FLERR, "fix wall/restitution: a 2D run (dimension 2) takes xplane or yplane");
}

void FixWallRestitution::setup(int vflag)
{
  post_force(vflag);
}

void FixWallRestitution::post_force(int /*vflag*/)
{
  double **x = atom->x, **v = atom->v, **f = atom->f;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *mask = atom->mask;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;

  contacts.begin();
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double gap = x[i][axis] - coord;
    if (gap >= radius[i]) continue;
    const double vn = v[i][axis];    // away from the wall: > 0

    Restitution::ContactState *state = contacts.find(i, 0);
    if (!state) {
      const double w = std::fabs(vn);
      double eps = 0.0, beta = 0.0;
      try {
        if (per_contact) {
          eps = contact.wall(w, estar, radius[i], rmass[i]).epsilon;
          beta = contact.beta(eps);
        } else {
          beta = table.first_touch(w, eps);
        }
      } catch (const Restitution::TableError &err) {
        error->one(FLERR, "fix wall/restitution, atom {} (type {}) on the wall: {}", tag[i],
                   atom->type[i], err.what());
      }
      state = contacts.open(i, 0, w, eps, beta);
      opened += 1.0;
    }

    double energy;
    f[i][axis] += Restitution::tsuji_normal_force(estar, radius[i], rmass[i], state->beta,
                                                  radius[i] - gap, -vn, energy);
  }
  contacts.sweep(nlocal);
}

double FixWallRestitution::compute_vector(int n)
{
  const double mine = n == 0 ? contacts.count(atom->nlocal, atom->tag, false) : opened;
  double all = 0.0;
  MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_SUM, world);
  return all;
}
