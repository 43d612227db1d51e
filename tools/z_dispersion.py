#!/usr/bin/env python3
"""Dispersion of the z-scores of null comparisons, from a study's report/cells.csv (standard library only).

A null comparison is a good generator against the reference (mt19937) run with identical settings: its shift
should be pure noise. Under a correct error model the shift divided by its standard error, mapped to the normal
scale through the model's own distribution (Student t on the model's degrees of freedom), has unit variance.
For each scalar observable this prints mean(z^2) over the null comparisons with its 95 % chi-square interval
(k degrees of freedom: z has mean 0 under the null), for three error models:

  runs      the runs' own block standard errors pooled over the replicas: se^2 = sum sem_i^2 / n^2 per side,
            normal (the block errors carry hundreds of degrees of freedom);
  pooled    the analysis's pooled t (replica spreads and block errors weighted by their degrees of freedom, the
            block errors left out when an F test at 5 % says the replicas vary more), dof as pooled;
  replicas  Student's two-sample t on the replicas' values alone, n + m - 2 degrees of freedom.

Variants sharing one reference share its noise, so their z-scores are positively correlated and the interval
is narrower than it should be; the ratio itself stays unbiased.

Usage: tools/z_dispersion.py results/okada2021/report/cells.csv [more cells.csv ...]
Good generators (as the analysis's known_good): philox4x32 at 7 rounds or more, threefry2x64 at 13 or more,
splitmix64, and tea32/tea64 at 16 rounds or more.
"""
import csv
import math
import sys
from collections import defaultdict
from statistics import NormalDist

OBSERVABLES = [("temperature_mean", "temperature_sem"), ("temperature_std", "temperature_std_sem"),
               ("pressure_mean", "pressure_sem"), ("diffusion_coefficient", "diffusion_sem")]
def good(gen, rounds):
    least = {"philox4x32": 7, "threefry2x64": 13, "splitmix64": 1, "tea32": 16, "tea64": 16}
    return gen in least and rounds >= least[gen]


def betacf(a, b, x):
    # Continued fraction of the regularized incomplete beta function (modified Lentz).
    tiny = 1e-300
    c, d = 1.0, 1.0 - (a + b) * x / (a + 1.0)
    d = 1.0 / (d if abs(d) > tiny else tiny)
    h = d
    for m in range(1, 500):
        m2 = 2 * m
        for num in (m * (b - m) * x / ((a + m2 - 1) * (a + m2)), -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1))):
            d = 1.0 + num * d
            d = 1.0 / (d if abs(d) > tiny else tiny)
            c = 1.0 + num / c
            c = c if abs(c) > tiny else tiny
            h *= d * c
        if abs(d * c - 1.0) < 1e-15:
            break
    return h


def betainc(a, b, x):
    if x <= 0:
        return 0.0
    if x >= 1:
        return 1.0
    lbt = math.lgamma(a + b) - math.lgamma(a) - math.lgamma(b) + a * math.log(x) + b * math.log1p(-x)
    if x < (a + 1) / (a + b + 2):
        return math.exp(lbt) * betacf(a, b, x) / a
    return 1.0 - math.exp(lbt) * betacf(b, a, 1 - x) / b


def t_cdf(t, dof):
    tail = 0.5 * betainc(dof / 2, 0.5, dof / (dof + t * t))
    return 1 - tail if t > 0 else tail


def f_sf(f, d1, d2):
    return betainc(d2 / 2, d1 / 2, d2 / (d2 + d1 * f))


def gammainc_p(a, x):
    if x <= 0:
        return 0.0
    if x < a + 1:
        s, term, n = 1.0 / a, 1.0 / a, a
        while abs(term) > 1e-16 * abs(s):
            n += 1
            term *= x / n
            s += term
        return s * math.exp(-x + a * math.log(x) - math.lgamma(a))
    # Continued fraction for Q.
    tiny = 1e-300
    b, c, d = x + 1 - a, 1 / tiny, 1 / (x + 1 - a)
    h = d
    for i in range(1, 1000):
        an = -i * (i - a)
        b += 2
        d = an * d + b
        d = 1 / (d if abs(d) > tiny else tiny)
        c = b + an / c
        c = c if abs(c) > tiny else tiny
        h *= d * c
        if abs(d * c - 1) < 1e-15:
            break
    return 1 - math.exp(-x + a * math.log(x) - math.lgamma(a)) * h


def chi2_quantile(p, k):
    lo, hi = 0.0, max(10.0, 10 * k)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if gammainc_p(k / 2, mid / 2) < p:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def z_of_t(t, dof):
    p = min(max(t_cdf(t, dof), 1e-300), 1 - 1e-16)
    return NormalDist().inv_cdf(p)


def mean(v):
    return sum(v) / len(v)


def squares(v):
    m = mean(v)
    return sum((x - m) ** 2 for x in v)


def z_scores(x, y):
    """x, y: lists of (value, sem, sem_dof). Returns {model: z}."""
    n, m = len(x), len(y)
    vx, vy = [a for a, _, _ in x], [a for a, _, _ in y]
    diff = mean(vx) - mean(vy)
    out = {}
    se_runs = math.sqrt(sum(s * s for _, s, _ in x) / n ** 2 + sum(s * s for _, s, _ in y) / m ** 2)
    out["runs"] = diff / se_runs
    ss, dof = squares(vx) + squares(vy), n + m - 2
    out["replicas"] = z_of_t(diff / math.sqrt(ss / dof * (1 / n + 1 / m)), dof)
    ess = sum(d * s * s for _, s, d in x + y)
    edof = sum(d for _, _, d in x + y)
    if f_sf((ss / dof) / (ess / edof), dof, edof) >= 0.05:
        ss, dof = ss + ess, dof + edof
    out["pooled"] = z_of_t(diff / math.sqrt(ss / dof * (1 / n + 1 / m)), dof)
    return out


def main(paths):
    z = defaultdict(list)  # (observable, model) -> z-scores
    for path in paths:
        groups = defaultdict(list)
        with open(path) as f:
            for row in csv.DictReader(f):
                if row.get("status", "ok") != "ok":
                    continue
                key = (row["generator"], int(row["rounds"]), row["distribution"], row.get("feed", "halves"),
                       row["seeding"], row["dt"], row.get("integrator", ""))
                groups[key].append(row)
        for key, rows in groups.items():
            gen, rounds, dist, feed, seeding, dt, integ = key
            if not good(gen, rounds):
                continue
            ref = [r for k, rs in groups.items() if k[0] == "mt19937" and k[2] == dist and k[3] == feed
                   and k[5] == dt and k[6] == integ for r in rs]
            if len(ref) < 2 or len(rows) < 2:
                continue
            for name, sem in OBSERVABLES:
                def take(rs):
                    return [(float(r[name]), float(r[sem]), float(r.get(sem + "_dof") or 19)) for r in rs
                            if r.get(name) and r.get(sem)]
                x, y = take(rows), take(ref)
                if len(x) < 2 or len(y) < 2:
                    continue
                for model, value in z_scores(x, y).items():
                    z[(name, model)].append(value)
    print("observable,model,comparisons,ratio,ci95_low,ci95_high")
    for name, _ in OBSERVABLES:
        for model in ("runs", "pooled", "replicas"):
            v = z[(name, model)]
            if not v:
                continue
            k = len(v)
            r = sum(a * a for a in v) / k
            print(f"{name},{model},{k},{r:.3f},{k * r / chi2_quantile(0.975, k):.3f},"
                  f"{k * r / chi2_quantile(0.025, k):.3f}")


if __name__ == "__main__":
    main(sys.argv[1:])
