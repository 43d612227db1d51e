# Compares two LAMMPS dumps of one step (tests/lammps/in.zeta with `forces`: "id fx fy fz" per atom, sorted by
# id, 17 significant digits: exact); the first is the reference. Prints "atoms N differ D relative R": the atoms
# whose force differs in any bit, and the largest component difference over the largest force component of the
# reference.
# Usage: awk -f force_compare.awk REF OTHER
function num(s) { return s + 0 }
FNR == 1 { atoms_section = 0 }
/^ITEM: ATOMS/ { atoms_section = 1; next }
/^ITEM:/ { atoms_section = 0; next }
!atoms_section { next }
FNR == NR { ref[$1] = $2 " " $3 " " $4; next }
{
  n++
  split(ref[$1], r, " ")
  if ($2 != r[1] || $3 != r[2] || $4 != r[3]) differ++
  for (k = 1; k <= 3; k++) {
    d = num($(k + 1)) - num(r[k])
    if (d < 0) d = -d
    if (d > maxd) maxd = d
    a = num(r[k])
    if (a < 0) a = -a
    if (a > maxf) maxf = a
  }
}
END { printf "atoms %d differ %d relative %.3g\n", n, differ + 0, (maxf > 0 ? maxd / maxf : 0) }
