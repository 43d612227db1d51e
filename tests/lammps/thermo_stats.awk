# Means and standard errors of k_BT, P and D from an in.water log (lammps/examples/in.water): each production
# block is one batch. T and P: the mean over the block's thermo rows (its first row, the previous block's last
# step, left out); D: the least-squares slope of the block's MSD against time over lags from 10 % of the block
# on (past the ballistic start), divided by 6. The standard error is that of the block means (blocks - 1 degrees
# of freedom). Prints: blocks B T mean se P mean se D mean se
# Usage: awk -v dt=0.04 -f thermo_stats.awk log.lammps
function flush_block(   k, sx, sy, sxx, sxy, m, t, lag0) {
  if (rows < 2) return
  nb++
  tsum = psum = 0
  for (k = 2; k <= rows; k++) { tsum += temp[k]; psum += press[k] }
  bt[nb] = tsum / (rows - 1); bp[nb] = psum / (rows - 1)
  lag0 = 0.1 * (step[rows] - step[1])
  sx = sy = sxx = sxy = m = 0
  for (k = 1; k <= rows; k++) {
    if (step[k] - step[1] < lag0) continue
    t = (step[k] - step[1]) * dt
    sx += t; sy += msd[k]; sxx += t * t; sxy += t * msd[k]; m++
  }
  bd[nb] = (m * sxy - sx * sy) / (m * sxx - sx * sx) / 6
}
function report(name, v,   k, mean, ss) {
  mean = 0
  for (k = 1; k <= nb; k++) mean += v[k]
  mean /= nb
  ss = 0
  for (k = 1; k <= nb; k++) ss += (v[k] - mean) ^ 2
  printf " %s %.8g %.4g", name, mean, sqrt(ss / (nb - 1) / nb)
}
/^ *Step / { inblock = ($0 ~ /c_msd\[4\]/); rows = 0; next }
/^Loop time/ { if (inblock) flush_block(); inblock = 0; next }
inblock && $1 ~ /^[0-9]+$/ { rows++; step[rows] = $1; temp[rows] = $2; press[rows] = $3; msd[rows] = $4 }
END {
  if (nb < 2) { print "thermo_stats.awk: fewer than 2 production blocks in the log" > "/dev/stderr"; exit 1 }
  printf "blocks %d", nb
  report("T", bt); report("P", bp); report("D", bd)
  printf "\n"
}
