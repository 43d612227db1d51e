#include "dpdrng/stats/curve_test.hpp"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>

#include "dpdrng/common/error.hpp"

namespace dpdrng::stats {

namespace {

std::vector<double> mean_curve(const Curves& c) {
  std::vector<double> m(c.front().size(), 0.0);
  for (const auto& v : c)
    for (std::size_t k = 0; k < m.size(); ++k) m[k] += v[k];
  for (double& x : m) x /= double(c.size());
  return m;
}

Curves residuals(const Curves& c) {
  const auto m = mean_curve(c);
  Curves out;
  for (const auto& v : c) {
    std::vector<double> r(v.size());
    for (std::size_t k = 0; k < v.size(); ++k) r[k] = v[k] - m[k];
    out.push_back(std::move(r));
  }
  return out;
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t k = 0; k < a.size(); ++k) s += a[k] * b[k];
  return s;
}

// tr(Σ̂) and tr(Σ̂²) of Σ̂ = Σ_g w_g Σ_{i∈g} r_i r_iᵀ, from the residuals' Gram matrix, never the bins × bins matrix.
struct Traces {
  double tr = 0, tr2 = 0, dof = 0;
};
Traces traces(const std::vector<Curves>& groups, const std::vector<double>& weight) {
  Traces t;
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (const auto& r : groups[g]) t.tr += weight[g] * dot(r, r);
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (std::size_t h = 0; h < groups.size(); ++h)
      for (const auto& a : groups[g])
        for (const auto& b : groups[h]) t.tr2 += weight[g] * weight[h] * std::pow(dot(a, b), 2);
  return t;
}

// d = tr(Σ)²/tr(Σ²) from a covariance estimate Σ̂ = W/ν, W ~ Wishart(ν, Σ): E[tr(Σ̂)²] = tr(Σ)² + 2 tr(Σ²)/ν and
// E[tr(Σ̂²)] = (1 + 1/ν) tr(Σ²) + tr(Σ)²/ν, solved for the two unknowns; the plug-in ratio if they come out
// non-positive.
double unbiased_d(const Traces& t) {
  const double nu = t.dof, c = (nu - 1.0) * (nu + 2.0);
  const double tr_sq = nu * (nu + 1.0) / c * (t.tr * t.tr - 2.0 * t.tr2 / (nu + 1.0));
  const double sq = nu * nu / c * (t.tr2 - t.tr * t.tr / nu);
  return tr_sq > 0 && sq > 0 ? tr_sq / sq : t.tr * t.tr / t.tr2;
}

// The runs' leave-one-block-out covariances pooled, each run's weighted by its blocks − 1: the jackknife
// covariance of a run is (B − 1)/B Σ_b (J_b − J̄)(J_b − J̄)ᵀ with B − 1 degrees of freedom.
Traces jackknife_traces(const std::vector<Curves>& runs, std::size_t bins) {
  std::vector<Curves> res;
  std::vector<double> blocks;
  double dof = 0;
  for (const auto& j : runs) {
    if (j.size() < 2) continue;
    for (const auto& c : j)
      if (c.size() != bins) throw InputError("curve test: jackknife curves of another length");
    res.push_back(residuals(j));
    blocks.push_back(double(j.size()));
    dof += double(j.size()) - 1.0;
  }
  std::vector<double> weight;
  for (const double b : blocks) weight.push_back((b - 1.0) / dof * (b - 1.0) / b);
  Traces t = traces(res, weight);
  t.dof = dof;
  return t;
}

}  // namespace

CurveTest curve_test(const Curves& x, const Curves& y, const std::vector<Curves>& jackknife) {
  CurveTest r;
  r.n = x.size();
  r.m = y.size();
  r.f = r.d = r.dof1 = r.dof2 = r.p_value = NAN;
  if (x.empty() || y.empty()) return r;
  r.bins = x.front().size();
  for (const auto* g : {&x, &y})
    for (const auto& v : *g)
      if (v.size() != r.bins) throw InputError("curve test: curves of different lengths");
  const double nu = double(r.n + r.m) - 2.0;
  if (nu < 2.0 || r.bins == 0) return r;

  Traces rep = traces({residuals(x), residuals(y)}, {1.0 / nu, 1.0 / nu});
  rep.dof = nu;
  if (!(rep.tr > 0)) return r;
  const auto mx = mean_curve(x), my = mean_curve(y);
  double between = 0;
  for (std::size_t k = 0; k < r.bins; ++k) between += (mx[k] - my[k]) * (mx[k] - my[k]);
  between *= double(r.n) * double(r.m) / double(r.n + r.m);
  r.f = between / rep.tr;

  const Traces runs = jackknife_traces(jackknife, r.bins);
  r.d_from_runs = runs.dof >= 2.0 && runs.tr > 0;
  r.d = r.d_from_runs ? unbiased_d(runs) : rep.tr * rep.tr / rep.tr2;
  r.d_dof = r.d_from_runs ? runs.dof : nu;
  r.d = std::clamp(r.d, 1.0, double(r.bins));
  r.dof1 = r.d;
  r.dof2 = r.d * nu;
  r.p_value = gsl_cdf_fdist_Q(r.f, r.dof1, r.dof2);
  return r;
}

}  // namespace dpdrng::stats
