// epsilon(w) of one type pair (or of a grain on the wall) and the universal map beta(epsilon),
// read from the table file that restitution.laws.exports.lammps_plugin.plugin_table writes.
//
// No LAMMPS here: the styles catch TableError and report it with error->all / error->one, and
// table_probe.cpp evaluates the same class outside LAMMPS (tests compare it with Python).
//
// Grammar (one item a line; '#' starts a comment line; blank lines are ignored):
//
//   restitution-table 1
//   units si
//   knots N
//   w_m_s epsilon slope_s_m                   (N lines, w strictly increasing, N >= 2)
//   below power L0 w0_m_s q                   1 - eps^2 = L0 (w / w0)^q
//     or
//   below log L0 w0_m_s ws_m_s p              1 - eps^2 = L0 (ln(ws / w0) / ln(ws / w))^p
//   beta-map M
//   epsilon beta dbeta_dlnepsilon             (M lines, epsilon strictly increasing, the last 1)
//   end
//
// Between knots epsilon(w) is the cubic Hermite polynomial of the knots' values and slopes;
// below the slowest knot w0 the continuation (eps = 1 at w = 0); above the fastest knot no
// value (Status::Above: the caller stops the run). beta(epsilon) is the cubic Hermite polynomial
// in ln(epsilon) of the map's knots (beta and d beta / d ln epsilon).

#ifndef RESTITUTION_TABLE_H
#define RESTITUTION_TABLE_H

#include <stdexcept>
#include <string>
#include <vector>

namespace Restitution {

namespace detail {
  class Reader;
}

class TableError : public std::runtime_error {
 public:
  explicit TableError(const std::string &what) : std::runtime_error(what) {}
};

class RestitutionTable {
 public:
  enum class Status { Inside = 0, Below = 1, Above = 2, BadSpeed = 3 };

  // Parse the file; throws TableError naming the file, the line and what is wrong.
  static RestitutionTable read(const std::string &path);
  static RestitutionTable parse(const std::string &text, const std::string &name);
  // The knots and the continuation alone ("knots N", the rows, the "below" line), read from a
  // file being read (the wall's elastic law in a file of the law per contact, contact_law.h):
  // epsilon() serves, beta() and first_touch() do not (no map).
  static RestitutionTable read_curve(detail::Reader &r, const std::string &name);

  // epsilon at impact speed w (m/s); NaN with status Above or BadSpeed.
  double epsilon(double w, Status &status) const;
  // beta of Tsuji's damping that gives restitution coefficient eps; throws TableError for an
  // eps outside [smallest map epsilon, 1].
  double beta(double eps) const;
  // At a contact's first touch with impact speed w (m/s): sets eps = epsilon(w) and returns
  // beta(eps); throws TableError (what to do in it) above the range, for a speed that is not
  // a finite number, or for an eps outside the map. The styles add who touched.
  double first_touch(double w, double &eps) const;

  double w_min() const { return w_.front(); }
  double w_max() const { return w_.back(); }
  double map_epsilon_min() const { return map_eps_.front(); }
  const std::string &name() const { return name_; }

 private:
  std::string name_;
  std::vector<double> w_, eps_, slope_;    // knots of epsilon(w)
  bool below_log_ = false;                 // continuation: power or log form
  double loss0_ = 0.0, w0_ = 0.0, exponent_ = 1.0, ws_ = 0.0;
  std::vector<double> map_eps_, map_lneps_, map_beta_, map_slope_;    // beta(ln epsilon)

  double below(double w) const;
  void check_curve() const;
  void check_map() const;
};

}    // namespace Restitution

#endif
