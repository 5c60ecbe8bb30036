// Per-contact state kept by the styles themselves (the wheel has no fix neigh/history): a hash
// map from the contact's atoms (two atom IDs for a pair, one for a grain on the wall) to what
// was fixed at its first touch. Every force evaluation marks the contacts it meets; sweep()
// then drops the others, so that a contact that has ended starts afresh when it closes again.
//
// The map lives on one MPI rank; the styles refuse to run on more than one (a contact whose
// atoms migrate would lose its state).

#ifndef RESTITUTION_CONTACT_STORE_H
#define RESTITUTION_CONTACT_STORE_H

#include <cstdint>
#include <unordered_map>

namespace Restitution {

struct ContactState {
  double w;          // impact speed at first touch, m/s
  double epsilon;    // the table's epsilon(w)
  double beta;       // Tsuji's damping coefficient for that epsilon
  std::uint64_t stamp;
};

class ContactStore {
 public:
  // The key of a contact of atom IDs a and b (either order; b = 0 for a wall contact): both IDs
  // in one word, exact for IDs below 2^32 (LAMMPS_SMALLBIG's 32-bit tagint; fits() checks).
  static std::uint64_t key(std::int64_t a, std::int64_t b)
  {
    std::uint64_t lo = static_cast<std::uint64_t>(a < b ? a : b);
    std::uint64_t hi = static_cast<std::uint64_t>(a < b ? b : a);
    return (hi << 32) | lo;
  }

  static bool fits(std::int64_t id) { return id >= 0 && id < (std::int64_t(1) << 32); }

  // Start a force evaluation.
  void begin() { ++stamp_; }

  // The state of the contact, marked as met; nullptr if it is new (then call open()).
  ContactState *find(std::int64_t a, std::int64_t b)
  {
    auto it = map_.find(key(a, b));
    if (it == map_.end()) return nullptr;
    it->second.stamp = stamp_;
    return &it->second;
  }

  ContactState *open(std::int64_t a, std::int64_t b, double w, double epsilon, double beta)
  {
    ++opened_;
    ContactState &s = map_[key(a, b)];
    s = ContactState{w, epsilon, beta, stamp_};
    return &s;
  }

  // Drop the contacts this evaluation did not meet.
  void sweep()
  {
    for (auto it = map_.begin(); it != map_.end();) {
      if (it->second.stamp != stamp_)
        it = map_.erase(it);
      else
        ++it;
    }
  }

  std::size_t live() const { return map_.size(); }
  std::uint64_t opened() const { return opened_; }

 private:
  std::unordered_map<std::uint64_t, ContactState> map_;
  std::uint64_t stamp_ = 0, opened_ = 0;
};

}    // namespace Restitution

#endif
