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
  if (head.words[1] != "1") r.fail("format version " + head.words[1] + " is not 1");
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
  } else {
    law.wall_ = RestitutionTable::read_curve(r, name);
  }

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

ContactLaw::Parts ContactLaw::sum(double elastic, double viscous, const std::string &what) const
{
  const double square = 1.0 - elastic - viscous;
  if (!(square >= map_min_ * map_min_))
    throw TableError(what + ": the losses to vibrations (" + number(elastic) +
                     ") and viscosity (" + number(viscous) + ") leave epsilon below " +
                     number(map_min_) + " (the plugin's least)");
  return Parts{std::sqrt(square), elastic, viscous};
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
  const double elastic = mstar / m1 * a.G(x1) + mstar / m2 * b.G(x2);
  return sum(elastic, viscous_loss(estar, rstar, mstar, w, what), what);
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
  const double elastic = 1.0 - eps_el * eps_el;
  return sum(elastic, viscous_loss(estar, r, m, w, what), what);
}

double ContactLaw::beta(double eps) const
{
  if (!(eps >= map_min_ && eps <= 1.0))
    throw TableError("restitution file " + name_ + ": epsilon " + number(eps) +
                     " lies outside the beta-map [" + number(map_min_) + ", 1]");
  return map_(std::log(eps));
}

}    // namespace Restitution
