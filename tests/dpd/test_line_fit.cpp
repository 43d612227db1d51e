// The least-squares line against exact data and against the normal equations solved by Eigen (an independent
// solver: a QR factorisation of the design matrix).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

#include "dpdrng/dpd/line_fit.hpp"

namespace dpdrng::dpd::test_line_fit {
namespace {

TEST(LineFit, RecoversAnExactLine) {
  // y = 1.5 − 0.25 x at x = 0, 0.5, …, 4.5: binary fractions, so every sum is exact.
  std::vector<double> x, y;
  for (int k = 0; k < 10; ++k) x.push_back(0.5 * k), y.push_back(1.5 - 0.25 * (0.5 * k));
  const LineFit f = fit_line(x, y);
  EXPECT_EQ(f.slope, -0.25);
  EXPECT_EQ(f.intercept, 1.5);
}

TEST(LineFit, ThreePointsByHand) {
  // (0, 1), (1, 2), (2, 6): Σx = 3, Σy = 9, Σx² = 5, Σxy = 14; b = (3·14 − 3·9)/(3·5 − 9) = 2.5, a = (9 − 7.5)/3.
  const std::vector<double> x{0, 1, 2}, y{1, 2, 6};
  const LineFit f = fit_line(x, y);
  EXPECT_DOUBLE_EQ(f.slope, 2.5);
  EXPECT_DOUBLE_EQ(f.intercept, 0.5);
}

TEST(LineFit, NoisyDataMatchTheNormalEquations) {
  std::mt19937_64 gen(11);
  std::uniform_real_distribution<double> noise(-0.3, 0.3);
  const int m = 200;
  std::vector<double> x(m), y(m);
  Eigen::MatrixXd A(m, 2);
  Eigen::VectorXd b(m);
  for (int k = 0; k < m; ++k) {
    x[k] = 0.05 * k + 0.37;
    y[k] = -2.0 + 0.8 * x[k] + noise(gen);
    A(k, 0) = 1.0, A(k, 1) = x[k], b(k) = y[k];
  }
  const Eigen::Vector2d ref = A.colPivHouseholderQr().solve(b);
  const LineFit f = fit_line(x, y);
  EXPECT_NEAR(f.intercept, ref(0), 1e-12);
  EXPECT_NEAR(f.slope, ref(1), 1e-12);
  EXPECT_NEAR(f.slope, 0.8, 0.05);  // and the noise is small enough for the line to show through
}

TEST(LineFit, DegenerateAbscissaeGiveZero) {
  const std::vector<double> x{2, 2, 2}, y{1, 5, 3}, one{1}, y1{4};
  EXPECT_EQ(fit_line(x, y).slope, 0.0);
  EXPECT_EQ(fit_line(one, y1).slope, 0.0);
  EXPECT_EQ(fit_line({}, {}).intercept, 0.0);
}

}  // namespace
}  // namespace dpdrng::dpd::test_line_fit
