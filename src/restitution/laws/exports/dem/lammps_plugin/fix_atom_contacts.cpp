// fix RESTITUTION_CONTACTS and the base of fix wall/restitution (fix_atom_contacts.h).

#include "fix_atom_contacts.h"

#include "atom.h"

using namespace LAMMPS_NS;
using namespace FixConst;

FixAtomContacts::FixAtomContacts(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  create_attribute = 1;    // an atom created during a run starts with no contacts
  maxexchange_dynamic = 1;
  maxexchange = 1;
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
}

FixAtomContacts::~FixAtomContacts()
{
  atom->delete_callback(id, Atom::GROW);
}

int FixAtomContacts::setmask()
{
  return PRE_EXCHANGE;
}

void FixAtomContacts::setup_pre_exchange()
{
  pre_exchange();
}

void FixAtomContacts::pre_exchange()
{
  // An atom received in one direction of an exchange may be sent on in the next: size the
  // buffer by the largest contact list on any rank.
  const int local = static_cast<int>(contacts.most(atom->nlocal));
  int most = 0;
  MPI_Allreduce(&local, &most, 1, MPI_INT, MPI_MAX, world);
  maxexchange = 1 + Restitution::AtomContacts::PACKED * most;
}

void FixAtomContacts::grow_arrays(int nmax)
{
  contacts.grow(nmax);
}

void FixAtomContacts::copy_arrays(int i, int j, int /*delflag*/)
{
  contacts.copy(i, j);
}

void FixAtomContacts::set_arrays(int i)
{
  contacts.clear(i);
}

int FixAtomContacts::pack_exchange(int i, double *buf)
{
  return contacts.pack(i, buf);
}

int FixAtomContacts::unpack_exchange(int nlocal, double *buf)
{
  return contacts.unpack(nlocal, buf);
}
