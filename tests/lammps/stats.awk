# Two-sample comparisons for physics.sh. Input lines: NAME MEAN1 SE1 DOF1 MEAN2 SE2 DOF2 LEVEL, LEVEL the
# two-sided confidence (0.95 or 0.999). Prints per line: NAME diff se dof low high, the CI of MEAN1 − MEAN2 with
# Welch–Satterthwaite degrees of freedom (rounded down), from Student's t quantiles in the table below.
function tq(level, dof,   k) {  # two-sided quantile of Student's t, for the table's dof at or below `dof`
  if (level == 0.95) { split("12.706 4.303 3.182 2.776 2.571 2.447 2.365 2.306 2.262 2.228 2.201 2.179 2.160 2.145 2.131", tab, " ") }
  else { split("636.62 31.599 12.924 8.610 6.869 5.959 5.408 5.041 4.781 4.587 4.437 4.318 4.221 4.140 4.073", tab, " ") }
  if (dof < 1) return "nan"
  if (dof <= 15) return tab[int(dof)]
  # beyond 15: 20, 30, 60, 120, infinity
  if (level == 0.95) { if (dof < 20) return 2.131; if (dof < 30) return 2.086; if (dof < 60) return 2.042; if (dof < 120) return 2.000; return 1.980 }
  if (dof < 20) return 4.073; if (dof < 30) return 3.850; if (dof < 60) return 3.646; if (dof < 120) return 3.460; return 3.373
}
{
  d = $2 - $5
  v1 = $3 * $3; v2 = $6 * $6
  se = sqrt(v1 + v2)
  dof = (v1 + v2) ^ 2 / (v1 * v1 / $4 + v2 * v2 / $7)
  q = tq($8, dof)
  printf "%s %.6g %.4g %d %.6g %.6g\n", $1, d, se, int(dof), d - q * se, d + q * se
}
