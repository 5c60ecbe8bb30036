// The law per contact's reader and evaluation (contact_law.h); the same operations, in the same
// order, as restitution.laws.exports.contact_law (the tests compare the two through the probe).

#include "contact_law.h"
#include "table_reader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace Restitution {

using detail::hermite;
using detail::interval;
using detail::Line;
using detail::Reader;

namespace {

  // Hertz's contact time over delta_max / w for a sphere: 2 sqrt(pi) Gamma(7/5) / Gamma(9/10).
  constexpr double KAPPA = 2.943275184324706;    // the Python constant's double, exactly

  std::string text_of(const std::string &path)
  {
    std::ifstream in(path);
    if (!in) throw TableError("cannot open restitution file " + path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  std::string number(double v)
  {
    std::ostringstream out;
    out.precision(8);
    out << v;
    return out.str();
  }

  // The rows of a curve, strictly increasing in x.
  HermiteCurve curve(Reader &r, long n, const std::string &form)
  {
    HermiteCurve c;
    r.rows(n, c.x, c.y, c.d, form);
    for (std::size_t k = 1; k < c.x.size(); ++k)
      if (!(c.x[k] > c.x[k - 1])) r.fail("the first column of the rows '" + form +
                                         "' must increase strictly");
    return c;
  }

}    // namespace

double HermiteCurve::operator()(double v) const
{
  std::size_t lo = interval(x, v);
  return hermite(v, x[lo], x[lo + 1], y[lo], y[lo + 1], d[lo], d[lo + 1]);
}

double ContactLaw::Material::G(double x) const
{
  if (x > loss.x.back()) return loss.y.back() * std::pow(loss.x.back() / x, power);
  return loss(x);
}

bool ContactLaw::is_contact_file(const std::string &path)
{
  for (const Line &line : detail::content_lines(text_of(path)))
    return line.words[0] == "restitution-contact";
  return false;
}

ContactLaw ContactLaw::read(const std::string &path)
{
  return parse(text_of(path), path);
}

ContactLaw ContactLaw::parse(const std::string &text, const std::string &name)
{
  ContactLaw law;
  law.name_ = name;
  Reader r(text, name);

  const Line &head = r.keyword("restitution-contact", 2, "restitution-contact 1");
  if (head.words[1] != "1" && head.words[1] != "2")
    r.fail("format version " + head.words[1] + " is not 1 or 2");
  law.plastic_ = head.words[1] == "2";
  const Line &units = r.keyword("units", 2, "units si");
  if (units.words[1] != "si") r.fail("units " + units.words[1] + " are not si");
  const Line &kind = r.keyword("contact", 2, "contact pair' or 'contact wall");
  if (kind.words[1] != "pair" && kind.words[1] != "wall")
    r.fail("the contact is 'pair' or 'wall', not '" + kind.words[1] + "'");
  law.pair_ = kind.words[1] == "pair";

  const Line &tau = r.keyword("relaxation-time", 2, "relaxation-time TAU_S");
  law.tau_ = r.number(tau, 1);
  if (!(law.tau_ >= 0.0)) r.fail("the relaxation time must be >= 0 s");

  const Line &vmap = r.keyword("viscous-map", 5, "viscous-map N C1 C2 H");
  const long nv = r.count(vmap, 1);
  law.c1_ = r.number(vmap, 2);
  law.c2_ = r.number(vmap, 3);
  law.h_ = r.number(vmap, 4);
  law.viscous_ = curve(r, nv, "ln_q epsilon_v depsilon_v_dlnq");
  for (double e : law.viscous_.y)
    if (!(e > 0.0 && e <= 1.0)) r.fail("viscous-map epsilons must lie in (0, 1]");

  if (law.plastic_) {
    const Line &flow = r.keyword("plastic-flow", 2, "plastic-flow P_Y_PA");
    law.p_y_ = r.number(flow, 1);
    if (!(law.p_y_ > 0.0)) r.fail("the limiting pressure must be > 0 Pa");
    if (law.tau_ != 0.0) r.fail("plastic flow with damping is not in the law per contact");
    if (!law.pair_) {
      const Line &mat = r.keyword("material", 4, "material E_PA NU RHO_KG_M3");
      const double E = r.number(mat, 1), nu = r.number(mat, 2), rho = r.number(mat, 3);
      if (!(E > 0.0 && rho > 0.0 && nu > -1.0 && nu < 0.5))
        r.fail("a material needs E > 0, -1 < nu < 0.5 and rho > 0");
      law.c_grain_ = std::sqrt(E / rho);
    }
  }

  if (law.pair_) {
    const Line &count = r.keyword("materials", 2, "materials K");
    const long k = r.integer(count, 1, 1, 2);
    for (long m = 0; m < k; ++m) {
      const Line &mat = r.keyword("material", 4, "material E_PA NU RHO_KG_M3");
      const double E = r.number(mat, 1), nu = r.number(mat, 2), rho = r.number(mat, 3);
      if (!(E > 0.0 && rho > 0.0 && nu > -1.0 && nu < 0.5))
        r.fail("a material needs E > 0, -1 < nu < 0.5 and rho > 0");
      Material one{};
      one.c = std::sqrt(E / rho);
      const Line &reach = r.keyword("reach", 3, "reach X_LO WIDTH_MAX");
      one.x_lo = r.number(reach, 1);
      one.width_max = r.number(reach, 2);
      if (!(one.x_lo > 0.0 && one.width_max > 0.0)) r.fail("the reach's numbers must be > 0");
      const Line &knots = r.keyword("loss-knots", 2, "loss-knots N");
      one.loss = curve(r, r.count(knots, 1), "x G dG_dx");
      if (std::fabs(one.loss.x.front() - one.x_lo) > 1e-12 * one.x_lo)
        r.fail("the first loss knot must be the reach's X_LO");
      for (double g : one.loss.y)
        if (!(g >= 0.0)) r.fail("the loss G must be >= 0");
      const Line &beyond = r.keyword("beyond", 3, "beyond power P");
      if (beyond.words[1] != "power") r.fail("expected 'beyond power P'");
      one.power = r.number(beyond, 2);
      if (!(one.power > 0.0)) r.fail("the power beyond the last knot must be > 0");
      law.materials_.push_back(one);
    }
    if (law.plastic_ && k != 1) r.fail("plastic flow is in the law per contact of one material");
  } else {
    law.wall_ = RestitutionTable::read_curve(r, name);
  }
  if (law.plastic_) law.read_ratio(r);

  const Line &map = r.keyword("beta-map", 2, "beta-map M");
  std::vector<double> eps, beta, slope;
  r.rows(r.count(map, 1), eps, beta, slope, "epsilon beta dbeta_dlnepsilon");
  r.keyword("end", 1, "end");
  if (!r.done()) r.fail("has lines after 'end'");
  for (std::size_t k = 0; k < eps.size(); ++k) {
    if (!(eps[k] > 0.0) || (k > 0 && !(eps[k] > eps[k - 1])) || !(beta[k] >= 0.0))
      throw TableError("restitution file " + name +
                       ": the beta-map's epsilons must be > 0 and increase, its betas >= 0");
    law.map_.x.push_back(std::log(eps[k]));
  }
  if (eps.back() != 1.0 || beta.back() != 0.0)
    throw TableError("restitution file " + name +
                     ": the beta-map must end at epsilon = 1, beta = 0");
  law.map_.y = beta;
  law.map_.d = slope;
  law.map_min_ = eps.front();
  return law;
}

void ContactLaw::read_ratio(Reader &r)
{
  const Line &head = r.keyword("wave-ratio", 3, "wave-ratio K ETA_STEP");
  const long k = r.count(head, 1);
  if (k < 4) r.fail("the wave ratio needs at least 4 knots in eta");
  eta_step_ = r.number(head, 2);
  if (!(eta_step_ > 0.0)) r.fail("the eta step must be > 0");
  for (long j = 0; j < k; ++j) {
    const Line &knot = r.keyword("eta-knot", 2, "eta-knot ETA");
    const double eta = r.number(knot, 1);
    if (std::fabs(eta - j * eta_step_) > 1e-12 * (1.0 + eta))
      r.fail("the eta knots must be 0, ETA_STEP, 2 ETA_STEP, ...");
    eta_.push_back(eta);
    const Line &count = r.keyword("ratio-knots", 2, "ratio-knots N");
    ratio_.push_back(curve(r, r.count(count, 1), "x r dr_dx"));
    if (ratio_.back().x != ratio_.front().x) r.fail("every eta knot needs the same x knots");
    for (double v : ratio_.back().y)
      if (!(v > 0.0)) r.fail("the wave ratio must be > 0");
  }
}

double ContactLaw::speed_over_yield(double w, double estar, double rstar, double mstar) const
{
  if (!plastic_) return 0.0;
  const double pi = 3.141592653589793;
  return w / std::sqrt(std::pow(pi, 5.0) / 30.0 * std::pow(p_y_, 5.0) * std::pow(rstar, 3.0) /
                       (std::pow(estar, 4.0) * mstar));
}

namespace {

  // Thornton's epsilon at u = w / v_y (restitution.quasistatic.plastic.thornton_epsilon).
  double thornton(double u)
  {
    if (u <= 1.0) return 1.0;
    const double s = u * u;
    const double x = (1.0 + std::sqrt((24.0 * s - 4.0) / 5.0)) / 3.0;
    return (3.0 * x - 1.0) / (2.0 * std::sqrt(s) * std::pow(x, 0.25));
  }

}    // namespace

double ContactLaw::ratio(double x, double u, double radius, const std::string &what) const
{
  if (u <= 1.0) return 1.0;
  const std::vector<double> &k = ratio_.front().x;
  const double u_top = std::cosh(eta_.back());
  if (!(u <= u_top))
    throw TableError(what + ": the impact speed is " + number(u) +
                     " times the contact's yield speed, beyond the " + number(u_top) +
                     " to which the table of the plastic pulse's waves reaches; no epsilon is "
                     "extrapolated");
  if (x < k.front())
    throw TableError(what + ": the contact time is " + number(x) +
                     " transit times of the grain of radius " + number(radius) +
                     " m, below the " + number(k.front()) +
                     " from which the package's estimate of its vibrations holds (the low-speed "
                     "route's reach); no epsilon is extrapolated");
  if (!(x <= k.back()))
    throw TableError(what + ": the contact time is " + number(x) +
                     " transit times of the grain of radius " + number(radius) +
                     " m, beyond the " + number(k.back()) +
                     " to which the table of the plastic pulse's waves reaches (a yielding "
                     "contact this slow against the grain's modes: a limiting pressure far below "
                     "this one's material); no epsilon is extrapolated");
  const double eta = std::acosh(u);
  const double h = eta_[1] - eta_[0];
  const long n = static_cast<long>(eta_.size());
  const long first = std::min(std::max(static_cast<long>(eta / h) - 1, 0L), n - 4);
  const std::size_t lo = interval(k, x);
  const double t = (eta - eta_[static_cast<std::size_t>(first)]) / h;
  double out = 0.0;
  for (int a = 0; a < 4; ++a) {
    double weight = 1.0;
    for (int b = 0; b < 4; ++b)
      if (b != a) weight *= (t - b) / static_cast<double>(a - b);
    const HermiteCurve &row = ratio_[static_cast<std::size_t>(first + a)];
    out += weight * hermite(x, k[lo], k[lo + 1], row.y[lo], row.y[lo + 1], row.d[lo],
                            row.d[lo + 1]);
  }
  return out;
}

double ContactLaw::viscous_loss(double estar, double rstar, double mstar, double w,
                                const std::string &what) const
{
  if (tau_ == 0.0) return 0.0;
  const double k = 4.0 / 3.0 * estar * std::sqrt(rstar);
  const double q = 1.5 * tau_ * std::pow(k / mstar, 0.4) * std::pow(w, 0.2);
  double eps;
  if (q < std::exp(viscous_.x.front())) {
    eps = 1.0 - c1_ * q + c2_ * q * q + h_ * std::pow(q, 2.5);
  } else {
    const double u = std::log(q);
    if (u > viscous_.x.back())
      throw TableError(what + ": the viscous loss alone leaves epsilon below " +
                       number(viscous_.y.back()) + " (the group q = " + number(q) +
                       " is above the viscous map's " + number(std::exp(viscous_.x.back())) +
                       "); no epsilon is extrapolated");
    eps = viscous_(u);
  }
  return 1.0 - eps * eps;
}

ContactLaw::Parts ContactLaw::sum(double elastic, double viscous, const std::string &what,
                                  double contact, double u) const
{
  const double square = contact * contact - elastic - viscous;
  if (!(square >= map_min_ * map_min_))
    throw TableError(what + ": the losses to vibrations (" + number(elastic) +
                     ") and viscosity (" + number(viscous) + ")" +
                     (contact == 1.0 ? std::string()
                                     : " with the plastic flow's (epsilon " + number(contact) +
                                      ")") +
                     " leave epsilon below " + number(map_min_) + " (the plugin's least)");
  return Parts{std::sqrt(square), elastic, viscous, contact, u};
}

ContactLaw::Parts ContactLaw::pair(double w, double estar, double r1, double m1, int i1,
                                   double r2, double m2, int i2) const
{
  if (!pair_) throw TableError("restitution file " + name_ + " holds a wall's law, not a pair's");
  if (!(w >= 0.0) || !std::isfinite(w))
    throw TableError("impact speed " + number(w) + " m/s is not a finite number");
  if (w == 0.0) return Parts{1.0, 0.0, 0.0};
  const Material &a = materials_.at(static_cast<std::size_t>(i1));
  const Material &b = materials_.at(static_cast<std::size_t>(i2));
  const std::string what = "impact at " + number(w) + " m/s of radii " + number(r1) + " and " +
      number(r2) + " m (law " + name_ + ")";

  const double rstar = r1 * r2 / (r1 + r2);
  const double mstar = m1 * m2 / (m1 + m2);
  const double k = 4.0 / 3.0 * estar * std::sqrt(rstar);
  const double dmax = std::pow(1.25 * mstar * w * w / k, 0.4);
  const double width = std::sqrt(rstar * dmax) / std::min(r1, r2);
  const double top = std::min(a.width_max, b.width_max);
  if (width > top)
    throw TableError(what + ": its contact radius is " + number(width) +
                     " of the smaller radius, beyond the " + number(top) +
                     " to which the package's estimate of the elastic waves reaches (the "
                     "low-speed route's reach); no epsilon is extrapolated");
  const double tc = KAPPA * dmax / w;
  const double x1 = tc * a.c / r1, x2 = tc * b.c / r2;
  for (int g = 0; g < 2; ++g) {
    const double x = g == 0 ? x1 : x2;
    const Material &mat = g == 0 ? a : b;
    if (x < mat.x_lo)
      throw TableError(what + ": the contact time is " + number(x) +
                       " transit times of the grain of radius " + number(g == 0 ? r1 : r2) +
                       " m, below the " + number(mat.x_lo) +
                       " from which the package's estimate of its vibrations holds (its lowest "
                       "mode is too slow against the contact: the low-speed route's reach); no "
                       "epsilon is extrapolated");
  }
  const double u = speed_over_yield(w, estar, rstar, mstar);
  double part1 = mstar / m1 * a.G(x1), part2 = mstar / m2 * b.G(x2);
  if (u > 1.0) {
    part1 *= ratio(x1, u, r1, what);
    part2 *= ratio(x2, u, r2, what);
  }
  const double elastic = part1 + part2;
  return sum(elastic, viscous_loss(estar, rstar, mstar, w, what), what, thornton(u), u);
}

ContactLaw::Parts ContactLaw::wall(double w, double estar, double r, double m) const
{
  if (pair_) throw TableError("restitution file " + name_ + " holds a pair's law, not a wall's");
  const std::string what = "impact at " + number(w) + " m/s of radius " + number(r) +
      " m on the wall (law " + name_ + ")";
  RestitutionTable::Status status;
  const double eps_el = wall_.epsilon(w, status);
  if (status == RestitutionTable::Status::Above)
    throw TableError(what + ": above the range " + number(wall_.w_min()) + " ... " +
                     number(wall_.w_max()) +
                     " m/s of the elastic wall law; no epsilon is extrapolated");
  if (status == RestitutionTable::Status::BadSpeed)
    throw TableError("impact speed " + number(w) + " m/s is not a finite number");
  double elastic = 1.0 - eps_el * eps_el;
  const double u = speed_over_yield(w, estar, r, m);
  if (u > 1.0) {
    const double k = 4.0 / 3.0 * estar * std::sqrt(r);
    const double dmax = std::pow(1.25 * m * w * w / k, 0.4);
    const double x = KAPPA * dmax / w * c_grain_ / r;
    elastic *= ratio(x, u, r, what);
  }
  return sum(elastic, viscous_loss(estar, r, m, w, what), what, thornton(u), u);
}

double ContactLaw::beta(double eps) const
{
  if (!(eps >= map_min_ && eps <= 1.0))
    throw TableError("restitution file " + name_ + ": epsilon " + number(eps) +
                     " lies outside the beta-map [" + number(map_min_) + ", 1]");
  return map_(std::log(eps));
}

}    // namespace Restitution
