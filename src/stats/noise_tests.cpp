#include "dpdrng/stats/noise_tests.hpp"

namespace dpdrng::stats {

namespace {
// The tests take contiguous spans; a row of the other storage order is strided, so it is gathered first.
template <class Get>
void gather(std::vector<double>& buf, std::size_t n, Get&& get) {
  buf.resize(n);
  for (std::size_t k = 0; k < n; ++k) buf[k] = get(k);
}
}  // namespace

std::vector<Chi2Result> chi2_per_step(const NoiseMatrix& u01, const Chi2Options& options) {
  std::vector<Chi2Result> out;
  out.reserve(u01.steps());
  std::vector<double> buf;
  for (std::size_t t = 0; t < u01.steps(); ++t) {
    gather(buf, u01.pairs(), [&](std::size_t p) { return u01(p, t); });
    out.push_back(chi2_uniform(buf, options));
  }
  return out;
}

std::vector<Lag1Result> lag1_per_pair(const NoiseMatrix& m, double alpha) {
  std::vector<Lag1Result> out;
  out.reserve(m.pairs());
  std::vector<double> buf;
  for (std::size_t p = 0; p < m.pairs(); ++p) {
    gather(buf, m.steps(), [&](std::size_t t) { return m(p, t); });
    out.push_back(lag1_ttest(buf, alpha));
  }
  return out;
}

}  // namespace dpdrng::stats
