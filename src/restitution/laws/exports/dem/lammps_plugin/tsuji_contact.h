// The normal force of one contact: Hertz's elastic force and Tsuji's damping.
//
//   F = (4/3) E* sqrt(R*) delta^(3/2) + beta sqrt(m* k) d(delta)/dt,  k = dF_el/d(delta)
//     = 2 E* sqrt(R* delta),
//
// repulsive when positive; delta the overlap (m), d(delta)/dt its rate (m/s, > 0 approaching),
// E* (Pa), R* (m) and m* (kg) the contact's reduced modulus, radius and mass. No tangential
// force. With this damping the coefficient of restitution depends on beta alone, not on the
// impact speed (docs/lammps-plugin.md): the styles fix beta per contact at its first touch.
// The force is not clipped at zero: near the end of a contact the damping outweighs the
// elastic force and pulls (the universal map beta(epsilon) is computed with the same force).

#ifndef RESTITUTION_TSUJI_CONTACT_H
#define RESTITUTION_TSUJI_CONTACT_H

#include <cmath>

namespace Restitution {

// Normal force (N, > 0 repulsive); energy gets the elastic energy (8/15) E* sqrt(R*) delta^(5/2)
// (J).
inline double tsuji_normal_force(double estar, double rstar, double mstar, double beta,
                                 double delta, double delta_rate, double &energy)
{
  const double stiffness = 2.0 * estar * std::sqrt(rstar * delta);
  const double elastic = (2.0 / 3.0) * stiffness * delta;
  energy = 0.4 * elastic * delta;
  return elastic + beta * std::sqrt(mstar * stiffness) * delta_rate;
}

}    // namespace Restitution

#endif
