// The stability study's judgements on its points (stability.hpp): each method's accuracy frontier read from the
// CIs, the integrators ranked by frontier and cost, and the crossing of noise error and integrator error.
#include <algorithm>
#include <cmath>

#include "dpdrng/common/numbers.hpp"
#include "dpdrng/study/stability.hpp"
#include "dpdrng/study/sweep.hpp"

namespace dpdrng::study {
namespace {

// A point's replica mean and 95 % half-width under the thermometer; NaN when it has none.
std::pair<double, double> reading(const StabilityPoint& p, Thermometer t) {
  return t == Thermometer::kinetic ? std::pair{p.temperature, p.temperature_ci}
                                   : std::pair{p.temperature_conf, p.temperature_conf_ci};
}

bool ci_inside(const StabilityPoint& p, Thermometer t, double tol) {
  const auto [m, h] = reading(p, t);
  return p.stable == p.replicas && std::abs(m - 1.0) + h < tol;
}

bool ci_outside(const StabilityPoint& p, Thermometer t, double tol) {
  if (p.stable < p.replicas) return true;  // a blow-up is outside any band
  const auto [m, h] = reading(p, t);
  return std::abs(m - 1.0) - h > tol;
}

double median_of_finite(std::vector<double> v) {
  std::erase_if(v, [](double x) { return !std::isfinite(x); });
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

const StabilityPoint* find_point(const StabilityAnalysis& a, const StabilityPoint& like, const std::string& generator,
                                 const std::string& noise) {
  for (const auto& p : a.points)
    if (p.integrator == like.integrator && p.gamma == like.gamma && p.dt == like.dt && p.generator == generator &&
        p.noise == noise)
      return &p;
  return nullptr;
}

bool resolved(double x, double h) { return std::isfinite(x) && std::isfinite(h) && std::abs(x) > h; }

}  // namespace

const char* to_string(Thermometer t) { return t == Thermometer::kinetic ? "kinetic" : "configurational"; }

Frontier accuracy_frontier(const StabilityAnalysis& a, const std::string& method, Thermometer t, double tolerance) {
  std::vector<const StabilityPoint*> pts;  // Δt ascending (analyse_stability's order)
  for (const auto& p : a.points)
    if (p.method() == method) pts.push_back(&p);
  Frontier f;
  for (const auto* p : pts)
    if (ci_inside(*p, t, tolerance)) f.inside = p->dt;
  for (const auto* p : pts) {
    if (std::isfinite(f.inside) && p->dt < f.inside) {
      if (ci_outside(*p, t, tolerance)) f.outside_below.push_back(p->dt);
      continue;
    }
    if (ci_outside(*p, t, tolerance)) {
      f.outside = p->dt;
      break;
    }
  }
  return f;
}

std::string bracket_text(const Frontier& f) {
  return (std::isfinite(f.inside) ? exact_decimal(f.inside) : std::string("none")) + " – " +
         (std::isfinite(f.outside) ? exact_decimal(f.outside) : std::string("none in the sweep"));
}

// The relative computation times Jdpd (van den Broek, Kuhn & Zielesny, J. Cheminform. 10, 25 (2018)) names for
// its integration types, GW-MVV = 1: GWMVV 1.0, S1MVV 1.1, SCMVV with one dissipative iteration 1.4 and with five
// 2.3, PNHLN 1.9. Quoted, not re-measured; other iteration counts have no named factor.
double jdpd_cost_factor(const std::string& integrator) {
  if (integrator.empty() || integrator.rfind("mvv:", 0) == 0) return 1.0;
  if (integrator == "shardlow") return 1.1;
  if (integrator.rfind("pnhln:", 0) == 0) return 1.9;
  if (integrator.rfind("scmvv:", 0) == 0) {
    const IntegratorSpec s = parse_integrator_spec(integrator);
    return s.iterations == 1 ? 1.4 : s.iterations == 5 ? 2.3 : NAN;
  }
  return NAN;
}

std::vector<IntegratorRank> rank_integrators(const StabilityAnalysis& a, double tolerance) {
  std::vector<IntegratorRank> out;
  // The reference generator under its first noise at the scene's γ: the scheme's own error, without the noise's.
  std::string noise;
  for (const auto& p : a.points)
    if (p.reference && p.gamma == 0) {
      noise = p.noise;
      break;
    }
  for (const auto& p : a.points) {
    if (!p.reference || p.gamma != 0 || p.noise != noise) continue;
    if (std::any_of(out.begin(), out.end(), [&](const IntegratorRank& r) { return r.method == p.method(); })) continue;
    IntegratorRank r;
    r.integrator = p.integrator, r.method = p.method();
    r.ranked_by = integrator_of(p.integrator, SceneParams{}).kind == dpd::Integrator::pnhln
                      ? Thermometer::configurational
                      : Thermometer::kinetic;
    r.kinetic = accuracy_frontier(a, r.method, Thermometer::kinetic, tolerance);
    r.configurational = accuracy_frontier(a, r.method, Thermometer::configurational, tolerance);
    std::vector<double> steps;
    for (const auto& q : a.points)
      if (q.method() == r.method) steps.push_back(q.step_seconds);
    r.step_seconds = median_of_finite(steps);
    const Frontier& f = r.ranked_by == Thermometer::kinetic ? r.kinetic : r.configurational;
    r.seconds_per_time = r.step_seconds / f.inside;
    r.jdpd_factor = jdpd_cost_factor(r.integrator);
    out.push_back(std::move(r));
  }
  double base = NAN;
  for (const auto& r : out)
    if (integrator_of(r.integrator, SceneParams{}).kind == dpd::Integrator::mvv) {
      base = r.step_seconds;
      break;
    }
  for (auto& r : out) r.relative_step_cost = r.step_seconds / base;
  // Larger inside Δt first; then the larger first outside Δt (the scheme fails later); then the cheaper per unit
  // of simulated time, and per step.
  const auto key = [](const IntegratorRank& r, bool outside) {
    const Frontier& f = r.ranked_by == Thermometer::kinetic ? r.kinetic : r.configurational;
    const double d = outside ? f.outside : f.inside;
    return std::isfinite(d) ? d : outside ? INFINITY : -1.0;
  };
  std::stable_sort(out.begin(), out.end(), [&](const IntegratorRank& x, const IntegratorRank& y) {
    if (key(x, false) != key(y, false)) return key(x, false) > key(y, false);
    if (key(x, true) != key(y, true)) return key(x, true) > key(y, true);
    const double cx = std::isfinite(x.seconds_per_time) ? x.seconds_per_time : INFINITY;
    const double cy = std::isfinite(y.seconds_per_time) ? y.seconds_per_time : INFINITY;
    if (cx != cy) return cx < cy;
    const double sx = std::isfinite(x.step_seconds) ? x.step_seconds : INFINITY;
    const double sy = std::isfinite(y.step_seconds) ? y.step_seconds : INFINITY;
    return sx < sy;
  });
  return out;
}

std::vector<CrossingRow> crossing_rows(const StabilityAnalysis& a) {
  std::vector<CrossingRow> out;
  for (const auto& p : a.points) {
    // PNHLN draws no pair noise: it has no noise error to cross.
    if (p.gamma != 0 || integrator_of(p.integrator, SceneParams{}).kind == dpd::Integrator::pnhln) continue;
    CrossingRow r;
    r.integrator = p.integrator, r.generator = p.generator, r.noise = p.noise, r.reference = p.reference, r.dt = p.dt;
    r.temperature = p.temperature, r.temperature_ci = p.temperature_ci;
    r.temperature_conf = p.temperature_conf, r.temperature_conf_ci = p.temperature_conf_ci;
    std::string ref_generator;
    for (const auto& q : a.points)
      if (q.reference) {
        ref_generator = q.generator;
        break;
      }
    const StabilityPoint* ref = find_point(a, p, ref_generator, p.noise);
    if (ref && std::isfinite(ref->temperature)) {
      r.integrator_error = ref->temperature - 1.0;
      r.integrator_error_ci = ref->temperature_ci;
    }
    if (p.reference) {
      r.cancellation = "not applicable: the reference has no noise error";
    } else if (!std::isfinite(p.temperature) || !ref || !std::isfinite(ref->temperature)) {
      r.cancellation = "not applicable: no stable replica of the variant or its reference";
    } else {
      r.noise_shift = p.temperature - ref->temperature;
      r.noise_shift_ci = std::hypot(p.temperature_ci, ref->temperature_ci);
      const bool opposite = resolved(r.noise_shift, r.noise_shift_ci) &&
                            resolved(r.integrator_error, r.integrator_error_ci) &&
                            (r.noise_shift > 0) != (r.integrator_error > 0);
      r.cancellation = !opposite ? "none" : std::abs(p.temperature - 1.0) <= p.temperature_ci ? "full" : "partial";
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace dpdrng::study
