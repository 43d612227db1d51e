# Compares the zeta records of two runs, each the concatenation of its ranks' files (lines "tag_lo tag_hi ghost
# bits", in.zeta): the first file is the reference. Prints one line of counts:
#   pairs <distinct pairs of the other run> missing <in the reference only> extra <in the other only>
#   differ <pairs whose zeta differs from the reference's> twice <pairs the other run evaluated twice>
#   disagree <pairs evaluated twice with two different zeta> wrongcount <pairs evaluated neither once nor, for a
#   ghost pair with newton_pair off, twice>
# Usage: awk -v newton=on|off -f zeta_compare.awk REF OTHER
FNR == NR { key = $1 " " $2; if (!(key in ref)) ref[key] = $4; next }
{
  key = $1 " " $2
  n[key]++
  if (key in z) { if (z[key] != $4) disagree++ } else z[key] = $4
  if ($3 == 1) ghost[key] = 1
}
END {
  for (key in z) {
    pairs++
    if (!(key in ref)) extra++
    else if (ref[key] != z[key]) differ++
    if (n[key] == 2) twice++
    want = (newton == "off" && (key in ghost)) ? 2 : 1
    if (n[key] != want) wrongcount++
  }
  for (key in ref) if (!(key in z)) missing++
  printf "pairs %d missing %d extra %d differ %d twice %d disagree %d wrongcount %d\n", pairs, missing + 0, extra + 0,
         differ + 0, twice + 0, disagree + 0, wrongcount + 0
}
