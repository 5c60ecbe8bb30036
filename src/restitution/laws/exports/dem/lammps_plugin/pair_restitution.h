// pair_style restitution: frictionless Hertz contact with Tsuji's damping, whose coefficient is
// fixed per contact from the tabulated epsilon(w) at the contact's impact speed.
//
//   pair_style restitution
//   pair_coeff i j E* file             (i <= j; every type pair explicitly, no mixing)
//
// The file is a table per type pair (restitution_table.h: epsilon(w) for one pair of radii) or
// a law per contact (contact_law.h: epsilon from each contact's own radii, masses and impact
// speed, for grains of any sizes); its first line says which. A law per contact of two
// materials is given for one pair of types i < j (its first material is type i's).
//
// E* (Pa): 1/E* = (1 - nu_i^2)/E_i + (1 - nu_j^2)/E_j. R* and m* come from the two atoms'
// radii and masses (atom_style sphere). Needs units si and comm_modify vel yes; runs on any
// number of MPI ranks, with newton on or off: the contacts travel with their atoms
// (fix_atom_contacts.h), each rank computes every contact of the atoms it owns (a newton-off
// list) and sums the forces on each atom in the order of the partners' IDs, so that a run gives
// the same numbers on any number of ranks (docs/lammps-plugin.md). compute pair restitution
// gives two numbers, summed over the ranks: the contacts open now, the contacts opened so far.

#ifndef RESTITUTION_PAIR_RESTITUTION_H
#define RESTITUTION_PAIR_RESTITUTION_H

#include "pair.h"
#include "contact_law.h"
#include "restitution_table.h"

#include <cstdint>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class PairRestitution : public Pair {
 public:
  PairRestitution(class LAMMPS *);
  ~PairRestitution() override;

  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;

 protected:
  double **estar;       // E* of each type pair, Pa
  int **table_of;       // index into tables of each type pair (-1: a law per contact)
  int **contact_of;     // index into contact_laws of each type pair (-1: a table)
  std::vector<Restitution::RestitutionTable> tables;
  std::vector<Restitution::ContactLaw> contact_laws;
  std::vector<int> first_type;    // the type of each law per contact's first material
  std::vector<double> maxrad;    // largest radius of each type, m
  class FixAtomContacts *store;    // the atoms' contacts, carried with them between ranks
  double opened;                   // contacts opened on this rank so far

  // One atom's force from one contact, summed in a fixed order (compute()).
  struct Push {
    int atom;                 // local index
    std::int64_t partner;     // the partner's atom ID
    double f[3];
  };
  std::vector<Push> pushes;

  void allocate();
};

}    // namespace LAMMPS_NS

#endif
