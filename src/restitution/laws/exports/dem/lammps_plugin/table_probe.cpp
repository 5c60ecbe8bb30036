// restitution_table_probe TABLE [w ...] [-- eps ...]: the table's epsilon(w) and beta(eps), as
// the plugin evaluates them, one per line ("w status epsilon" / "eps beta") with 17 digits.
// Lets tests compare the C++ reader and interpolants with the Python side, without LAMMPS.

#include "restitution_table.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

int main(int argc, char **argv)
{
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s TABLE [w ...] [-- eps ...]\n", argv[0]);
    return 2;
  }
  try {
    auto table = Restitution::RestitutionTable::read(argv[1]);
    bool speeds = true;
    for (int k = 2; k < argc; ++k) {
      if (std::strcmp(argv[k], "--") == 0) {
        speeds = false;
        continue;
      }
      char *end = nullptr;
      double value = std::strtod(argv[k], &end);
      if (end == argv[k] || *end != '\0') {
        std::fprintf(stderr, "not a number: %s\n", argv[k]);
        return 2;
      }
      if (speeds) {
        Restitution::RestitutionTable::Status status;
        double eps = table.epsilon(value, status);
        std::printf("w %.17g %d %.17g\n", value, static_cast<int>(status), eps);
      } else {
        std::printf("eps %.17g %.17g\n", value, table.beta(value));
      }
    }
  } catch (const Restitution::TableError &err) {
    std::fprintf(stderr, "%s\n", err.what());
    return 1;
  }
  return 0;
}
