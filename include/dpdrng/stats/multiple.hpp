#pragma once
// Many P-values at once: Holm's adjustment over a family of tests, and Stouffer's combination of one test
// repeated on independent replicas.
#include <span>
#include <vector>

namespace dpdrng::stats {

// Holm's step-down adjusted P-values (Holm, Scand. J. Statist. 6 (1979) 65; R's p.adjust(p, "holm")): with the
// m finite P-values sorted, p_(1) ≤ … ≤ p_(m), adjusted p_(i) = max_{j ≤ i} min(1, (m − j + 1) p_(j)).
// Rejecting where the adjusted value is below α keeps the family-wise error rate at α under any dependence
// between the tests. NaN entries are not part of the family and stay NaN; the order of the input is kept.
std::vector<double> holm_adjust(std::span<const double> p);

// Stouffer's combination of two-sided P-values of independent replicas of one test, each with the sign of
// its effect: z_i = sign_i · Φ⁻¹(1 − p_i/2), Z = Σ z_i / √k, two-sided P of Z. Effects that point in
// different directions cancel, as a real bias would not. NaN entries are left out; NaN if none is left.
double stouffer_two_sided(std::span<const double> p, std::span<const double> sign);

}  // namespace dpdrng::stats
