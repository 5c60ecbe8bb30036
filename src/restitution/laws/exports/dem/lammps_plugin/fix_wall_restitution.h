// fix wall/restitution: a static frictionless plane; each grain's contact with it is Hertz's
// with Tsuji's damping, the damping coefficient fixed per contact from the tabulated epsilon(w)
// at the speed towards the wall at first touch.
//
//   fix ID group wall/restitution E* file xplane|yplane|zplane coord
//
// The file is a table (restitution_table.h: epsilon(w) of one radius) or a law per contact
// (contact_law.h, "contact wall": the elastic wall law with each grain's own viscous loss from
// its radius and mass); its first line says which.
//
// The grains sit on the + side of the plane (coordinate > coord). E* (Pa): 1/E* = (1 -
// nu^2)/E (+ (1 - nu_w^2)/E_w for an elastic wall); R* = the grain's radius, m* = its mass.
// zplane needs dimension 3. Needs units si; runs on any number of MPI ranks (each grain's wall
// contact travels with it, fix_atom_contacts.h). Global vector of 2, summed over the ranks: the
// contacts open now, the contacts opened so far.

#ifndef RESTITUTION_FIX_WALL_RESTITUTION_H
#define RESTITUTION_FIX_WALL_RESTITUTION_H

#include "fix_atom_contacts.h"
#include "contact_law.h"
#include "restitution_table.h"

#include <string>

namespace LAMMPS_NS {

class FixWallRestitution : public FixAtomContacts {
 public:
  FixWallRestitution(class LAMMPS *, int, char **);

  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  double compute_vector(int) override;

 protected:
  double estar;        // Pa
  int axis;            // 0, 1, 2: the plane's normal
  double coord;        // the plane's position along axis, m
  Restitution::RestitutionTable table;
  bool per_contact;                      // the file is a law per contact
  Restitution::ContactLaw contact;
  double opened;       // contacts opened on this rank so far
};

}    // namespace LAMMPS_NS

#endif
