// restitution_table_probe FILE ...: the plugin's readers and interpolants outside LAMMPS, one
// answer per line with 17 digits, so that tests compare the C++ with Python.
//
//   A table (restitution_table.h):      restitution_table_probe TABLE [w ...] [-- eps ...]
//     "w <w> <status> <epsilon>" and "eps <eps> <beta>".
//   A law per contact (contact_law.h):  restitution_table_probe LAW QUERY ...
//     pair W ESTAR R1 M1 I1 R2 M2 I2  -> "pair ok <epsilon> <elastic> <viscous> <beta>"
//     wall W ESTAR R M                -> "wall ok <epsilon> <elastic> <viscous> <beta>"
//     (or "<pair|wall> outside <message>" where the law has no value)

#include "contact_law.h"
#include "restitution_table.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

bool number(const char *word, double &value)
{
  char *end = nullptr;
  value = std::strtod(word, &end);
  if (end == word || *end != '\0') {
    std::fprintf(stderr, "not a number: %s\n", word);
    return false;
  }
  return true;
}

int probe_table(int argc, char **argv)
{
  auto table = Restitution::RestitutionTable::read(argv[1]);
  bool speeds = true;
  for (int k = 2; k < argc; ++k) {
    if (std::strcmp(argv[k], "--") == 0) {
      speeds = false;
      continue;
    }
    double value;
    if (!number(argv[k], value)) return 2;
    if (speeds) {
      Restitution::RestitutionTable::Status status;
      double eps = table.epsilon(value, status);
      std::printf("w %.17g %d %.17g\n", value, static_cast<int>(status), eps);
    } else {
      std::printf("eps %.17g %.17g\n", value, table.beta(value));
    }
  }
  return 0;
}

int probe_contact(int argc, char **argv)
{
  auto law = Restitution::ContactLaw::read(argv[1]);
  for (int k = 2; k < argc;) {
    const bool pair = std::strcmp(argv[k], "pair") == 0;
    if (!pair && std::strcmp(argv[k], "wall") != 0) {
      std::fprintf(stderr, "expected 'pair' or 'wall', got %s\n", argv[k]);
      return 2;
    }
    const int n = pair ? 8 : 4;
    if (k + n >= argc) {
      std::fprintf(stderr, "%s needs %d numbers\n", argv[k], n);
      return 2;
    }
    double v[8];
    for (int i = 0; i < n; ++i)
      if (!number(argv[k + 1 + i], v[i])) return 2;
    k += n + 1;
    try {
      auto p = pair ? law.pair(v[0], v[1], v[2], v[3], static_cast<int>(v[4]), v[5], v[6],
                               static_cast<int>(v[7]))
                    : law.wall(v[0], v[1], v[2], v[3]);
      std::printf("%s ok %.17g %.17g %.17g %.17g\n", pair ? "pair" : "wall", p.epsilon,
                  p.elastic, p.viscous, law.beta(p.epsilon));
    } catch (const Restitution::TableError &err) {
      std::printf("%s outside %s\n", pair ? "pair" : "wall", err.what());
    }
  }
  return 0;
}

}    // namespace

int main(int argc, char **argv)
{
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FILE [queries] (table_probe.cpp says which)\n", argv[0]);
    return 2;
  }
  try {
    if (Restitution::ContactLaw::is_contact_file(argv[1])) return probe_contact(argc, argv);
    return probe_table(argc, argv);
  } catch (const Restitution::TableError &err) {
    std::fprintf(stderr, "%s\n", err.what());
    return 1;
  }
}
