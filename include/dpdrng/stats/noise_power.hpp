#pragma once
// The noise's effective power as the force receives it, the temperature shift it predicts, and the shift
// between two independent runs' estimates with its confidence interval.
#include <cmath>
#include <span>

namespace dpdrng::stats {

// An estimate with its standard error (se) on dof degrees of freedom; dof = ∞ for a normal error.
struct Measured {
  double mean = NAN, se = NAN, dof = INFINITY;
};

// Δ = a − b of two independent estimates: se² = se_a² + se_b², Welch–Satterthwaite degrees of freedom
// (se_a² + se_b²)² / (se_a⁴/ν_a + se_b⁴/ν_b), and the two-sided Student-t interval at `confidence`.
struct Shift {
  double delta = NAN, se = NAN, dof = NAN, low = NAN, high = NAN;
};
Shift independent_shift(const Measured& a, const Measured& b, double confidence = 0.95);

// A pair's ζ enters the random force as σ w_R ζ /√Δt, and the heat the force puts in over many steps is set by the
// power of that sequence at low frequency: the w_R²-weighted second moment ⟨w_R²ζ²⟩/⟨w_R²⟩ (m2w) times
// 1 + 2 Σ_{k=1}^{K} ρ_k, the sum over a pair's ζ autocorrelation at lags 1…K (the integrated autocorrelation
// time's factor). An independent unit-variance ζ gives 1.
struct NoisePower {
  double value = NAN, se = NAN;
};
// m2w and ρ_k with their standard errors (independent errors, propagated to first order).
NoisePower effective_noise_power(const Measured& m2w, std::span<const Measured> rho);

// The kinetic temperature's ratio to the reference's at the same settings, T/T_ref ≈ P/P_ref of the two noises'
// effective powers (the thermostat balances the heat in against γ's friction, which is the same for both), with
// the ratio's first-order standard error.
NoisePower predicted_temperature_ratio(const NoisePower& variant, const NoisePower& reference);

}  // namespace dpdrng::stats
