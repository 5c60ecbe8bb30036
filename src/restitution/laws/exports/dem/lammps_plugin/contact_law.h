// The law per contact: epsilon of a contact from its own radii, masses, modulus E* and impact speed
// w, read from the file that restitution.laws.exports.contact_file.contact_law_file writes
// (docs/lammps-plugin.md, "A law per contact"). No LAMMPS here: the styles catch TableError and
// stop the run with it; table_probe.cpp evaluates the same class outside LAMMPS.
//
//   1 - epsilon^2 = L_el + L_v
//
// * L_el, the elastic waves. Two spheres: (m*/m1) G1(x1) + (m*/m2) G2(x2), x_i = t_c c_i / R_i,
//   t_c = kappa delta_max / w Hertz's contact time (kappa = 2.9432752, delta_max = (5 m* w^2 /
//   (4 K))^(2/5), K = (4/3) E* sqrt(R*)), c_i = sqrt(E_i / rho_i) of grain i's material and G_i
//   its curve (cubic Hermite in x; G_N (x_N / x)^P above the last knot). Served within the
//   package's reach only: x_i >= X_LO of each grain, sqrt(R* delta_max) / min(R1, R2) <=
//   WIDTH_MAX. A grain on the wall: the wall's law epsilon_el(w), L_el = 1 - epsilon_el^2.
// * L_v = 1 - epsilon_v(q)^2, q = (3/2) tau (K / m*)^(2/5) w^(1/5) (cubic Hermite in ln q; the
//   series 1 - C1 q + C2 q^2 + H q^(5/2) below the first knot; no value above the last); 0 for
//   tau = 0.
// * Plastic flow (format version 2): with the contact's yield speed v_y = sqrt((pi^5 / 30) p_y^5
//   R*^3 / (E*^4 m*)) and u = w / v_y, epsilon^2 = epsilon_T(u)^2 - L_el r, Thornton's closed
//   form epsilon_T (1 for u <= 1) and each sphere's wave loss times r(x_i, u) (1 for u <= 1):
//   cubic Hermite in x at the four nearest knots in eta = arccosh(u), Lagrange's cubic through
//   them in eta (restitution.laws.exports.plastic_waves). One material, no damping.
//
// Grammar (one item a line, '#' starts a comment line):
//
//   restitution-contact 1 | restitution-contact 2   (2: with plastic flow)
//   units si
//   contact pair | contact wall
//   relaxation-time TAU_S
//   viscous-map N C1 C2 H
//   ln_q epsilon_v depsilon_v_dlnq                 (N rows, ln q strictly increasing)
//   version 2:  plastic-flow P_Y_PA
//               material E_PA NU RHO_KG_M3         (a wall only: the grain's)
//   pair:  materials K                             (1: both grains; 2: type i's, then type j's)
//          material E_PA NU RHO_KG_M3              (K times: these four items)
//          reach X_LO WIDTH_MAX
//          loss-knots N
//          x G dG_dx                               (N rows, x strictly increasing from X_LO)
//          beyond power P
//   wall:  knots N / w_m_s epsilon slope_s_m rows / below ...   (as restitution_table.h)
//   version 2:  wave-ratio K ETA_STEP               (K knots in eta = arccosh(u) from 0)
//               eta-knot ETA / ratio-knots N / x r dr_dx rows   (K times)
//   beta-map M
//   epsilon beta dbeta_dlnepsilon                  (M rows, the last 1 0 ...)
//   end

#ifndef RESTITUTION_CONTACT_LAW_H
#define RESTITUTION_CONTACT_LAW_H

#include "restitution_table.h"

#include <string>
#include <vector>

namespace Restitution {

// Cubic Hermite through knots (x, y, dy/dx), x strictly increasing; for x[0] <= v <= x.back().
struct HermiteCurve {
  std::vector<double> x, y, d;
  double operator()(double v) const;
};

class ContactLaw {
 public:
  // Whether the file's first content line is "restitution-contact ..." (else it is a table per
  // type pair); throws TableError if it cannot be read.
  static bool is_contact_file(const std::string &path);
  static ContactLaw read(const std::string &path);
  static ContactLaw parse(const std::string &text, const std::string &name);

  // epsilon and its parts; throws TableError (what to do in it) where the law has no value.
  struct Parts {
    double epsilon, elastic, viscous;
    double contact = 1.0;    // Thornton's epsilon (1 without plastic flow)
    double u = 0.0;          // w / v_y (0 without plastic flow)
  };
  // Two grains: radius (m), mass (kg) and material index (0, or 1 for the second of two).
  Parts pair(double w, double estar, double r1, double m1, int i1, double r2, double m2,
             int i2) const;
  // A grain on the wall.
  Parts wall(double w, double estar, double r, double m) const;
  // beta of Tsuji's damping for eps; throws TableError outside the map.
  double beta(double eps) const;

  bool is_pair() const { return pair_; }
  bool is_plastic() const { return plastic_; }
  int materials() const { return static_cast<int>(materials_.size()); }
  const std::string &name() const { return name_; }

 private:
  struct Material {
    double c;            // sqrt(E / rho), m/s
    double x_lo;         // the route's least x
    double width_max;    // the route's largest contact radius over the smaller radius
    double power;        // G ~ x^-power above the last knot
    HermiteCurve loss;   // G(x)
    double G(double x) const;
  };

  std::string name_;
  bool pair_ = true;
  double tau_ = 0.0;
  double c1_ = 0.0, c2_ = 0.0, h_ = 0.0;    // the viscous series below the first knot
  HermiteCurve viscous_;                     // epsilon_v(ln q)
  std::vector<Material> materials_;
  RestitutionTable wall_;                    // the wall's elastic law (no map)
  HermiteCurve map_;                         // beta(ln epsilon)
  double map_min_ = 0.0;
  bool plastic_ = false;
  double p_y_ = 0.0;                         // Thornton's limiting pressure, Pa
  double c_grain_ = 0.0;                     // the wall's grain: sqrt(E / rho), m/s
  double eta_step_ = 0.0;
  std::vector<double> eta_;                  // knots in arccosh(u)
  std::vector<HermiteCurve> ratio_;          // r(x) at each eta knot

  double viscous_loss(double estar, double rstar, double mstar, double w,
                      const std::string &what) const;
  Parts sum(double elastic, double viscous, const std::string &what, double contact = 1.0,
            double u = 0.0) const;
  double speed_over_yield(double w, double estar, double rstar, double mstar) const;
  double ratio(double x, double u, double radius, const std::string &what) const;
  void read_ratio(detail::Reader &r);
};

}    // namespace Restitution

#endif
