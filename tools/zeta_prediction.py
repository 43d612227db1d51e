#!/usr/bin/env python3
"""Predicted against measured temperature shift over every study under a results directory.

For each study directory RESULTS/<study>/ this reads report/zeta.csv, which `dpdrng study report` writes: per
variant the shift of k_BT against the reference that the effective noise power predicts
(power_predicted_T_shift: the force's w_R^2-weighted <zeta^2> times 1 + 2 sum_k rho_k, over the reference's)
with its standard error, and the shift measured against the reference at the same settings with its 95 % CI.
It writes one table, RESULTS/zeta_prediction.csv by default: a row per variant, the agreement flag
("agrees" when the 95 % interval of predicted - measured holds 0, "fails" when it does not, "not applicable"
when either side is missing) and, where it is not "agrees", the reason in words. Each row is its own 95 %
check: over many rows a correct prediction fails about one time in twenty, as the summary line says.

A study whose report has no zeta.csv, or a zeta.csv written before the effective power was predicted, gets
one row saying so. Python 3 standard library only.

Usage: tools/zeta_prediction.py [RESULTS_DIR] [-o OUT.csv]
"""
import argparse
import csv
import math
import os
import sys

Z95 = 1.959963984540054
LARGE_SHIFT = 0.10  # beyond this the first-order link T/T_ref = P/P_ref is not expected to hold

COLUMNS = ["study", "variant", "generator", "rounds", "distribution", "feed", "seeding", "dt", "integrator",
           "replicas", "predicted_T_shift", "predicted_ci_low", "predicted_ci_high", "power_lags",
           "measured_T_shift", "measured_ci_low", "measured_ci_high", "z", "agreement", "reason"]


def number(row, key):
    """The row's value as a float, or None when the column is absent or empty."""
    text = (row.get(key) or "").strip()
    if not text:
        return None
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def fmt(x, pattern="{:.6g}"):
    return "" if x is None else pattern.format(x)


def pct(x):
    return "{:+.2f} %".format(100 * x)


def measured_interval(row):
    """The measured shift with its 95 % CI (the comparison's own where stored, else 1.96 sigma)."""
    m = number(row, "measured_T_shift")
    if m is None:
        return None, None, None, None
    sigma = number(row, "measured_T_shift_sigma")
    low, high = number(row, "measured_T_shift_ci_low"), number(row, "measured_T_shift_ci_high")
    if (low is None or high is None) and sigma is not None:
        low, high = m - Z95 * sigma, m + Z95 * sigma
    if sigma is None and low is not None and high is not None:
        sigma = (high - low) / (2 * Z95)
    return m, low, high, sigma


def judge(predicted, se, lags, measured, sigma):
    """(z, agreement, reason) of one variant."""
    if predicted is None:
        return None, "not applicable", "no effective-power prediction (the cells hold no weighted <zeta^2>)"
    if measured is None:
        return None, "not applicable", "no measured temperature shift against the reference"
    if se is None or sigma is None or not (se ** 2 + sigma ** 2 > 0):
        return None, "not applicable", "no standard error on one side"
    z = (predicted - measured) / math.sqrt(se ** 2 + sigma ** 2)
    if abs(z) <= Z95:
        return z, "agrees", ""
    reasons = ["measured {} against predicted {} ({:+.1f} sigma)".format(pct(measured), pct(predicted), z)]
    if predicted != 0 and measured * predicted > 0:
        reasons.append("measured {:.2g} x the prediction".format(measured / predicted))
    elif measured * predicted < 0 and abs(measured) > Z95 * sigma and abs(predicted) > Z95 * se:
        reasons.append("opposite signs")
    if max(abs(measured), abs(predicted)) > LARGE_SHIFT:
        reasons.append("a shift beyond 10 %: the first-order T/T_ref = P/P_ref does not hold there")
    if lags == 0:
        reasons.append("no autocorrelation of zeta stored (lags 0), so correlation across steps is left out")
    return z, "fails", "; ".join(reasons)


def variant_rows(study, rows):
    out = []
    for row in rows:
        if row.get("seeding") == "stream":  # the reference: its shift against itself is 0 by definition
            continue
        predicted = number(row, "power_predicted_T_shift")
        se = number(row, "power_predicted_T_shift_se")
        lags = number(row, "power_lags")
        measured, low, high, sigma = measured_interval(row)
        z, agreement, reason = judge(predicted, se, lags, measured, sigma)
        p_low = predicted - Z95 * se if predicted is not None and se is not None else None
        p_high = predicted + Z95 * se if predicted is not None and se is not None else None
        out.append({
            "study": study, "variant": "{}({})".format(row.get("generator", ""), row.get("rounds", "")),
            "generator": row.get("generator", ""), "rounds": row.get("rounds", ""),
            "distribution": row.get("distribution", ""), "feed": row.get("feed", ""),
            "seeding": row.get("seeding", ""), "dt": row.get("dt", ""), "integrator": row.get("integrator", ""),
            "replicas": row.get("replicas", ""), "predicted_T_shift": fmt(predicted),
            "predicted_ci_low": fmt(p_low), "predicted_ci_high": fmt(p_high),
            "power_lags": fmt(lags, "{:.0f}"), "measured_T_shift": fmt(measured), "measured_ci_low": fmt(low),
            "measured_ci_high": fmt(high), "z": fmt(z, "{:.3g}"), "agreement": agreement, "reason": reason,
        })
    return out


def study_note(study, reason):
    row = {c: "" for c in COLUMNS}
    row.update({"study": study, "agreement": "not applicable", "reason": reason})
    return row


def study_rows(results, study):
    path = os.path.join(results, study, "report", "zeta.csv")
    if not os.path.isfile(path):
        return [study_note(study, "its report has no zeta.csv")]
    with open(path, newline="", encoding="utf-8") as f:
        reader = csv.DictReader(f)
        rows = list(reader)
        header = reader.fieldnames or []
    if "power_predicted_T_shift" not in header:
        return [study_note(study, "its zeta.csv predates the effective-power prediction: rerun "
                                  "`dpdrng study report` on cells that store zeta_weighted_second_moment")]
    out = variant_rows(study, rows)
    return out or [study_note(study, "its zeta.csv holds no variant besides the reference")]


def studies_in(results):
    """Study directories (those `dpdrng study run` made: they hold study.toml), in name order."""
    return [name for name in sorted(os.listdir(results))
            if os.path.isfile(os.path.join(results, name, "study.toml"))]


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results", nargs="?", default="results", help="directory of study directories")
    parser.add_argument("-o", "--out", help="output CSV (default: RESULTS/zeta_prediction.csv)")
    args = parser.parse_args(argv)
    if not os.path.isdir(args.results):
        print("zeta_prediction: RESULTS_DIR {!r} is not a directory".format(args.results), file=sys.stderr)
        return 2
    studies = studies_in(args.results)
    if not studies:
        print("zeta_prediction: no study directory under {!r}".format(args.results), file=sys.stderr)
        return 2
    rows = []
    for study in studies:
        rows.extend(study_rows(args.results, study))
    out = args.out or os.path.join(args.results, "zeta_prediction.csv")
    with open(out + ".tmp", "w", newline="", encoding="utf-8") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS, lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
    os.replace(out + ".tmp", out)
    counts = {}
    for r in rows:
        counts[r["agreement"]] = counts.get(r["agreement"], 0) + 1
    judged = counts.get("agrees", 0) + counts.get("fails", 0)
    print("{}: {} rows from {} studies ({}); a correct prediction fails the 95 % check by chance in about {:.1f} "
          "of the {} judged rows".format(out, len(rows), len(studies),
                                         ", ".join("{} {}".format(v, k) for k, v in sorted(counts.items())),
                                         0.05 * judged, judged))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
