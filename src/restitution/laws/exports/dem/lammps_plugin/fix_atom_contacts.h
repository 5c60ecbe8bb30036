// A fix whose per-atom data is the contacts of each atom (contact_store.h): the per-atom
// callbacks that keep them with their atoms when LAMMPS sorts, deletes or creates atoms and when
// Comm::exchange moves an atom to another MPI rank. fix wall/restitution derives from it; pair
// restitution creates one (style RESTITUTION_CONTACTS, ID RESTITUTION_CONTACTS_PAIR) for its own
// contacts, as the GRANULAR pair styles create their fix neigh/history.
//
//   fix ID group-ID RESTITUTION_CONTACTS   (internal: pair restitution makes it)
//
// The exchange buffer of an atom grows with its contacts: before each exchange the largest
// number of contacts of any atom (over all ranks) sets maxexchange (maxexchange_dynamic).

#ifndef RESTITUTION_FIX_ATOM_CONTACTS_H
#define RESTITUTION_FIX_ATOM_CONTACTS_H

#include "contact_store.h"
#include "fix.h"

namespace LAMMPS_NS {

class FixAtomContacts : public Fix {
 public:
  FixAtomContacts(class LAMMPS *, int, char **);
  ~FixAtomContacts() override;

  int setmask() override;
  void setup_pre_exchange() override;
  void pre_exchange() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;

  Restitution::AtomContacts contacts;
};

}    // namespace LAMMPS_NS

#endif
