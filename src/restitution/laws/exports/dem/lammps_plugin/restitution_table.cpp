// The table file's reader and its two interpolants (grammar in restitution_table.h).

#include "restitution_table.h"
#include "table_reader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

namespace Restitution {

using detail::hermite;
using detail::interval;
using detail::Line;
using detail::Reader;

RestitutionTable RestitutionTable::read(const std::string &path)
{
  std::ifstream in(path);
  if (!in) throw TableError("cannot open restitution table file " + path);
  std::stringstream text;
  text << in.rdbuf();
  return parse(text.str(), path);
}

RestitutionTable RestitutionTable::parse(const std::string &text, const std::string &name)
{
  Reader r(text, name);

  const Line &head = r.keyword("restitution-table", 2, "restitution-table 1");
  if (head.words[1] != "1") r.fail("format version " + head.words[1] + " is not 1");
  const Line &units = r.keyword("units", 2, "units si");
  if (units.words[1] != "si") r.fail("units " + units.words[1] + " are not si");

  RestitutionTable t = read_curve(r, name);

  const Line &map = r.keyword("beta-map", 2, "beta-map M");
  r.rows(r.count(map, 1), t.map_eps_, t.map_beta_, t.map_slope_,
         "epsilon beta dbeta_dlnepsilon");
  r.keyword("end", 1, "end");
  if (!r.done()) r.fail("has lines after 'end'");

  for (double e : t.map_eps_) t.map_lneps_.push_back(std::log(e));
  t.check_map();
  return t;
}

RestitutionTable RestitutionTable::read_curve(detail::Reader &r, const std::string &name)
{
  RestitutionTable t;
  t.name_ = name;
  const Line &knots = r.keyword("knots", 2, "knots N");
  r.rows(r.count(knots, 1), t.w_, t.eps_, t.slope_, "w_m_s epsilon slope_s_m");

  const Line &below = r.next("'below power L0 w0 q' or 'below log L0 w0 ws p'");
  if (below.words[0] != "below") r.fail("expected 'below power ...' or 'below log ...'");
  if (below.words.size() == 5 && below.words[1] == "power") {
    t.below_log_ = false;
    t.loss0_ = r.number(below, 2);
    t.w0_ = r.number(below, 3);
    t.exponent_ = r.number(below, 4);
  } else if (below.words.size() == 6 && below.words[1] == "log") {
    t.below_log_ = true;
    t.loss0_ = r.number(below, 2);
    t.w0_ = r.number(below, 3);
    t.ws_ = r.number(below, 4);
    t.exponent_ = r.number(below, 5);
  } else {
    r.fail("expected 'below power L0 w0 q' or 'below log L0 w0 ws p'");
  }
  t.check_curve();
  return t;
}

// The table's promises, checked once at load so that a lookup cannot meet a bad knot.
void RestitutionTable::check_curve() const
{
  auto fail = [this](const std::string &what) {
    throw TableError("restitution table " + name_ + ": " + what);
  };
  for (std::size_t k = 0; k < w_.size(); ++k) {
    if (!(w_[k] > 0.0)) fail("knot speeds must be > 0 m/s");
    if (k > 0 && !(w_[k] > w_[k - 1])) fail("knot speeds must increase strictly");
    if (!(eps_[k] > 0.0 && eps_[k] <= 1.0)) fail("knot epsilons must lie in (0, 1]");
  }
  if (std::fabs(w0_ - w_.front()) > 1e-12 * w_.front())
    fail("the continuation's w0 must be the slowest knot's speed");
  if (!(loss0_ >= 0.0 && loss0_ < 1.0)) fail("the continuation's L0 must lie in [0, 1)");
  if (!(exponent_ > 0.0)) fail("the continuation's exponent must be > 0");
  if (below_log_ && !(ws_ > w0_)) fail("the log continuation needs ws > w0");
}

void RestitutionTable::check_map() const
{
  auto fail = [this](const std::string &what) {
    throw TableError("restitution table " + name_ + ": " + what);
  };
  for (std::size_t k = 0; k < map_eps_.size(); ++k) {
    if (!(map_eps_[k] > 0.0)) fail("beta-map epsilons must be > 0");
    if (k > 0 && !(map_eps_[k] > map_eps_[k - 1])) fail("beta-map epsilons must increase");
    if (!(map_beta_[k] >= 0.0)) fail("beta-map betas must be >= 0");
  }
  if (map_eps_.back() != 1.0 || map_beta_.back() != 0.0)
    fail("the beta-map must end at epsilon = 1, beta = 0");
  double lowest = *std::min_element(eps_.begin(), eps_.end());
  if (lowest < map_eps_.front())
    fail("its smallest epsilon " + std::to_string(lowest) +
         " lies below the beta-map's smallest " + std::to_string(map_eps_.front()));
}

double RestitutionTable::below(double w) const
{
  if (w == 0.0) return 1.0;
  double ratio;
  if (below_log_)
    ratio = std::pow(std::log(ws_ / w0_) / std::log(ws_ / w), exponent_);
  else
    ratio = std::pow(w / w0_, exponent_);
  return std::sqrt(1.0 - loss0_ * ratio);
}

double RestitutionTable::epsilon(double w, Status &status) const
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (!(w >= 0.0) || !std::isfinite(w)) {
    status = Status::BadSpeed;
    return nan;
  }
  if (w < w_.front()) {
    status = Status::Below;
    return below(w);
  }
  if (w > w_.back()) {
    status = Status::Above;
    return nan;
  }
  status = Status::Inside;
  std::size_t lo = interval(w_, w);
  return hermite(w, w_[lo], w_[lo + 1], eps_[lo], eps_[lo + 1], slope_[lo], slope_[lo + 1]);
}

double RestitutionTable::first_touch(double w, double &eps) const
{
  Status status;
  eps = epsilon(w, status);
  if (status == Status::Inside || status == Status::Below) return beta(eps);
  std::ostringstream msg;
  msg.precision(8);
  if (status == Status::Above)
    msg << "impact at " << w << " m/s is above the range " << w_min() << " ... " << w_max()
        << " m/s of table " << name_
        << "; no epsilon is extrapolated: give a table that reaches this speed";
  else
    msg << "impact speed " << w << " m/s is not a finite number";
  throw TableError(msg.str());
}

double RestitutionTable::beta(double eps) const
{
  if (map_eps_.empty()) throw TableError("restitution table " + name_ + " has no beta-map");
  if (!(eps >= map_eps_.front() && eps <= 1.0)) {
    std::ostringstream msg;
    msg.precision(10);
    msg << "restitution table " << name_ << ": epsilon " << eps << " lies outside the beta-map ["
        << map_eps_.front() << ", 1]";
    throw TableError(msg.str());
  }
  const double u = std::log(eps);
  std::size_t lo = interval(map_lneps_, u);
  return hermite(u, map_lneps_[lo], map_lneps_[lo + 1], map_beta_[lo], map_beta_[lo + 1],
                 map_slope_[lo], map_slope_[lo + 1]);
}

}    // namespace Restitution
