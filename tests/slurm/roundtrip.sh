#!/usr/bin/env bash
# A study through a real Slurm and back: starts a throw-away single-node Slurm (its own munged, slurmctld and
# slurmd, every file under one temporary directory, ports of its own, no cgroups, no accounting) and submits
# study/ci.toml with study/slurm/submit.sh as a 2-shard job array plus the merge job, twice:
#   1. shard 2 is killed (SIGKILL) after storing two cells: the merge job must not run;
#   2. the same command again: shard 1 must compute nothing, shard 2 only the cells it lacks, and the merge job
#      must assemble every cell and write a report that says so.
# Then it runs the config in one process and checks that the merged study.h5 equals that run's bit for bit.
#
# Compared: `h5dump -m %.17g` of both study.h5 files (17 significant digits tell any two doubles apart, so equal
# text means equal bits), with the attributes that measure the run rather than the physics removed: `seconds`,
# `cost.*` (timings and the numbers-per-step count beside them) and `note.cost.*` (the CPU the costs were measured
# on) — the same ones tests/study/test_cli_study.cpp's fingerprint leaves out. Every other attribute, every
# dataset (g(r), MSD, velocity PDF, jackknife rows, χ² and t P-values, NIST tables, the temperature series) and
# the list of cell files must match.
#
# Usage: tests/slurm/roundtrip.sh DPDRNG
# Needs root and the slurm-wlm and munge packages (./study/install-deps.sh slurm); installs nothing.
# Exit: 0 equal, 1 a mismatch, a failed job or a timeout, 2 bad arguments, 77 skipped (not root, or a Slurm or
# munge binary missing; one line says which).
# Environment: DPDRNG_SLURM_TIMEOUT (seconds to wait for each submission, default 300); DPDRNG_SLURM_KEEP=1 keeps
# the temporary directory; DPDRNG_SLURM_INJECT=fail-shard (shard 2 exits 1 in both submissions) or alter-cell
# (one bit of one g(r) value in the merged study.h5 flipped before the comparison) checks that the test fails
# when it should.
set -euo pipefail

skip() { echo "slurm round trip: skipped: $*" >&2; exit 77; }
fail() { echo "slurm round trip: FAILED: $*" >&2; exit 1; }
log() { echo "[slurm round trip ${SECONDS}s] $*" >&2; }

(($# == 1)) || { echo "usage: tests/slurm/roundtrip.sh DPDRNG" >&2; exit 2; }
[[ -x $1 ]] || { echo "slurm round trip: '$1' is not an executable" >&2; exit 2; }
dpdrng=$(realpath "$1")
repo=$(cd "$(dirname "$0")/../.." && pwd)
config=$repo/study/ci.toml
timeout_s=${DPDRNG_SLURM_TIMEOUT:-300}
inject=${DPDRNG_SLURM_INJECT:-}
case $inject in ""|fail-shard|alter-cell) ;; *) echo "DPDRNG_SLURM_INJECT: unknown '$inject'" >&2; exit 2 ;; esac

# Skips: only what this machine cannot provide. Anything after this point that goes wrong is a failure.
((EUID == 0)) || skip "not root (slurmd runs jobs as their user and needs root)"
for b in munged slurmctld slurmd sbatch squeue scontrol scancel sinfo h5dump; do
  command -v "$b" >/dev/null || skip "$b not found (./study/install-deps.sh slurm)"
done

tmp=$(mktemp -d /tmp/dpdrng-slurm.XXXXXX)
chmod 700 "$tmp"  # munged refuses a socket directory others can write to
pids=()
jobs_submitted=()
jobs_done=0
cleanup() {
  local rc=$?
  set +e
  # Cancel our jobs first so that their slurmstepd and dpdrng processes end before slurmd does.
  if ((${#jobs_submitted[@]})) && [[ -n ${SLURM_CONF:-} ]]; then
    scancel "${jobs_submitted[@]}" 2>/dev/null
    for _ in $(seq 30); do
      [[ -z $(squeue -h -o %i 2>/dev/null) ]] && break
      sleep 1
    done
  fi
  # Only the daemons this script started, by pid; slurmd and slurmctld end on SIGTERM, munged too.
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do kill "${pids[i]}" 2>/dev/null; done
  for p in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$p" 2>/dev/null || break; sleep 0.2; done
    kill -0 "$p" 2>/dev/null && { echo "slurm round trip: pid $p ignores SIGTERM: killed" >&2; kill -9 "$p"; }
  done
  # The daemons' and jobs' logs, when Slurm or a job is what failed.
  if ((rc != 0 && rc != 77 && !jobs_done)) && [[ -d $tmp ]]; then
    for f in "$tmp"/log/slurm*.log "$tmp"/out/slurm/*.log; do
      [[ -s $f ]] && { echo "---- $f (last 15 lines)" >&2; tail -n 15 "$f" >&2; }
    done
  fi
  if [[ ${DPDRNG_SLURM_KEEP:-0} == 1 ]]; then echo "kept $tmp" >&2; else rm -rf "$tmp"; fi
  exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

mkdir -p "$tmp"/{log,state,spool,munge,run}

# munge: a fresh key and a private socket, so that a system munged (if any) is neither needed nor disturbed.
dd if=/dev/urandom of="$tmp/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$tmp/munge/munge.key"
socket=$tmp/munge/munge.socket
# The daemons run in sessions of their own: a TERM sent to this script's process group (timeout(1), Ctrl-C)
# reaches this script, whose trap cancels the jobs before it stops them, not the daemons first.
setsid munged --foreground --force --key-file="$tmp/munge/munge.key" --socket="$socket" \
  --pid-file="$tmp/run/munged.pid" --log-file="$tmp/log/munged.log" --seed-file="$tmp/munge/seed" 2>>"$tmp/log/munged.log" &
pids+=($!)
for _ in $(seq 50); do [[ -S $socket ]] && break; sleep 0.2; done
[[ -S $socket ]] || fail "munged did not create its socket"

# Two free TCP ports, so a system Slurm on 6817/6818 (or a second copy of this test) does not collide.
free_port() {
  local p
  for _ in $(seq 100); do
    p=$((20000 + RANDOM % 20000))
    if ! (: >"/dev/tcp/127.0.0.1/$p") 2>/dev/null; then echo "$p"; return; fi
  done
  fail "no free TCP port found"
}
ctld_port=$(free_port)
slurmd_port=$(free_port)
while ((slurmd_port == ctld_port)); do slurmd_port=$(free_port); done

host=$(hostname -s)
# The node as slurmd itself sees it (CPUs, sockets, cores, memory), so that the node is not drained for a
# mismatch; the address is loopback so that the host name need not resolve.
node=$(slurmd -C | head -n 1)
[[ $node == NodeName=* ]] || fail "slurmd -C printed no NodeName line: $node"
cpus=$(sed -n 's/.* CPUs=\([0-9]*\).*/\1/p' <<<"$node")
cat >"$tmp/slurm.conf" <<EOF
ClusterName=dpdrngtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/run/slurmctld.pid
SlurmdPidFile=$tmp/run/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
# No cgroups (a container may not delegate them): plain process tracking, no task binding.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
# Cores are the consumable (not memory): the two one-core shards run side by side.
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
# A job whose afterok can never be met (a shard failed) is cancelled instead of pending for ever.
DependencyParameters=kill_invalid_depend
ReturnToService=2
# No mail (the default MailProg may be absent).
MailProg=/bin/true
MinJobAge=600
$node NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$tmp/slurm.conf

log "starting slurmctld and slurmd ($host, $cpus CPUs, ports $ctld_port/$slurmd_port, files in $tmp)"
setsid slurmctld -D -i -f "$SLURM_CONF" >"$tmp/log/slurmctld.stderr" 2>&1 &
pids+=($!)
setsid slurmd -D -f "$SLURM_CONF" >"$tmp/log/slurmd.stderr" 2>&1 &
pids+=($!)

# Wait for the node to register idle; a daemon that died on its config ends the wait at once.
state=""
for _ in $(seq 120); do
  for p in "${pids[@]}"; do
    kill -0 "$p" 2>/dev/null || { cat "$tmp"/log/*.stderr >&2; fail "a daemon (pid $p) exited while starting"; }
  done
  state=$(sinfo -h -N -o %T 2>/dev/null | head -n 1) || true
  [[ $state == idle ]] && break
  sleep 0.5
done
[[ $state == idle ]] || fail "the node is '${state:-unknown}' after 60 s, not idle"
log "node idle"

out=$tmp/out
q() { printf %q "$1"; }
# A dpdrng for the jobs whose shard 2 is killed (SIGKILL, as by a node failure or the OOM killer) once it has
# stored two cells; shard 1 and everything else run the real one. With fail-shard, shard 2 instead exits 1 at
# once, every time (the resubmission fails too).
killing=$tmp/dpdrng-kills-shard-2
cat >"$killing" <<EOF
#!/usr/bin/env bash
[[ " \$* " == *" --shard 2/"* ]] || exec $(q "$dpdrng") "\$@"
$(q "$dpdrng") "\$@" &
pid=\$!
for _ in \$(seq 1200); do
  n=\$(compgen -G $(q "$out/shard-2/cells")'/*.h5' | wc -l)   # finished cells; temporaries are hidden
  if ((n >= 2)); then kill -KILL \$pid; echo "killed shard 2 after \$n cells" >&2; exit 137; fi
  kill -0 \$pid 2>/dev/null || break
  sleep 0.1
done
wait \$pid
EOF
failing=$tmp/dpdrng-fails-shard-2
cat >"$failing" <<EOF
#!/usr/bin/env bash
[[ " \$* " == *" --shard 2/"* ]] && { echo "injected failure of shard 2" >&2; exit 1; }
exec $(q "$dpdrng") "\$@"
EOF
chmod +x "$killing" "$failing"

terminal='^(COMPLETED|FAILED|CANCELLED|TIMEOUT|NODE_FAIL|OUT_OF_MEMORY|BOOT_FAIL|DEADLINE|PREEMPTED|NEVER)$'
# "TASK:STATE" per array task of job $1 (a pending array not yet split: "pending:PENDING"), from slurmctld's
# memory (no accounting database; MinJobAge keeps finished jobs for 10 minutes). A job whose dependency can no
# longer be met shows NEVER, should kill_invalid_depend not have cancelled it yet.
states() {
  scontrol -o show job "$1" 2>/dev/null | awk '{
    t = "job"; s = ""; r = ""
    for (i = 1; i <= NF; i++) {
      if ($i ~ /^ArrayTaskId=/) t = substr($i, 13)
      if ($i ~ /^JobState=/) s = substr($i, 10)
      if ($i ~ /^Reason=/) r = substr($i, 8)
    }
    if (t ~ /[^0-9]/) t = "pending"
    if (s == "PENDING" && r == "DependencyNeverSatisfied") s = "NEVER"
    print t ":" s }' | sort
}
# Submits the study (dpdrng $1) and waits until every shard and the merge job have ended; sets shard_id,
# merge_id, shard_states ("1:COMPLETED 2:FAILED") and merge_state.
submit_and_wait() {
  local ids deadline all x
  ids=$("$repo/study/slurm/submit.sh" "$config" "$out" --shards 2 --cpus-per-task 1 --partition test \
          --dpdrng "$1") || fail "submit.sh failed"
  shard_id=$(awk '$1 == "shards" {print $2}' <<<"$ids")
  merge_id=$(awk '$1 == "merge" {print $2}' <<<"$ids")
  [[ $shard_id =~ ^[0-9]+$ && $merge_id =~ ^[0-9]+$ ]] || fail "submit.sh printed no job ids: $ids"
  jobs_submitted+=("$shard_id" "$merge_id")
  log "submitted: shards $shard_id, merge $merge_id"
  deadline=$((SECONDS + timeout_s))
  while :; do
    shard_states=$(states "$shard_id" | tr '\n' ' ')
    merge_state=$(states "$merge_id" | cut -d: -f2)
    all=1
    for x in $shard_states "job:$merge_state"; do [[ ${x#*:} =~ $terminal ]] || all=0; done
    ((all)) && break
    ((SECONDS < deadline)) || fail "jobs not done after ${timeout_s}s (shards: $shard_states; merge: $merge_state)"
    sleep 1
  done
  log "ended: shards $shard_states; merge $merge_state"
}
finished_in() { grep -o 'done in .*' "$out/slurm/shard-${shard_id}_$1.log" || echo "(no summary line)"; }
shard_cells() { "$dpdrng" study cells "$config" --shard "$1/2" | grep -c .; }

# First submission: shard 2 killed mid-run, so the merge job must never run.
submit_and_wait "$([[ $inject == fail-shard ]] && echo "$failing" || echo "$killing")"
[[ $merge_state == CANCELLED || $merge_state == NEVER ]] \
  || fail "merge job $merge_id is $merge_state after a failed shard (expected CANCELLED)"
[[ ! -e $out/study.h5 ]] || fail "the merge ran although a shard failed"
kept=$(compgen -G "$out/shard-2/cells/*.h5" | wc -l) || true
if [[ $inject != fail-shard ]]; then
  [[ $shard_states == "1:COMPLETED 2:FAILED " ]] || fail "first submission: shards $shard_states (expected 1 done, 2 killed)"
  ((kept >= 2)) || fail "the killed shard 2 left $kept whole cells (expected at least 2)"
fi

# Resubmission, the same command: only the missing cells are computed.
submit_and_wait "$([[ $inject == fail-shard ]] && echo "$failing" || echo "$dpdrng")"
[[ $shard_states == "1:COMPLETED 2:COMPLETED " ]] || fail "resubmission: shards ended $shard_states"
[[ $merge_state == COMPLETED ]] || fail "resubmission: merge job $merge_id ended $merge_state"
jobs_done=1
n1=$(shard_cells 1) n2=$(shard_cells 2)
finished_in 1 | grep -q ": 0 computed, $n1 resumed," || fail "resubmitted shard 1 recomputed cells: $(finished_in 1)"
finished_in 2 | grep -q ": $((n2 - kept)) computed, $kept resumed," \
  || fail "resubmitted shard 2 did not resume its $kept cells: $(finished_in 2)"
log "resubmission: shard 1 $(finished_in 1); shard 2 $(finished_in 2)"
ncells=$("$dpdrng" study cells "$config" | grep -c .)
grep -q "cells stored: \*\*$ncells of $ncells\*\*" "$out/report/report.md" \
  || fail "the merged report does not say $ncells of $ncells cells stored"

if [[ $inject == alter-cell ]]; then
  # The last bit of one g(r) value of one cell: the smallest change a double can take.
  ds=/cells/tea32-r01-gauss-inverse-distance-dt0.04-rep00/rdf/g
  offset=$(h5dump -p -H -d "$ds" "$out/study.h5" | awk '$1 == "OFFSET" {print $2}')
  [[ $offset =~ ^[0-9]+$ ]] || fail "inject: no contiguous storage for $ds"
  byte=$(od -An -tu1 -j $((offset + 8 * 50)) -N1 "$out/study.h5" | tr -d ' ')
  # shellcheck disable=SC2059  # the format is the one-byte octal escape, built on purpose
  printf "\\$(printf %03o $((byte ^ 1)))" | dd of="$out/study.h5" bs=1 seek=$((offset + 8 * 50)) conv=notrunc status=none
  log "inject: flipped the lowest bit of ${ds}[50] in the merged study.h5"
fi

log "the same config in one process"
"$dpdrng" study run "$config" --out "$tmp/one" --threads "$cpus" 2>"$tmp/log/one.log" \
  || { tail -n 5 "$tmp/log/one.log" >&2; fail "the one-process run failed"; }

# The physics of a store as text: h5dump at full precision minus the run-measuring attributes (each a block from
# its ATTRIBUTE line to the brace at its own indentation) and minus the first line, which names the file.
physics() {
  h5dump -m '%.17g' "$1" | sed 1d | awk '
    skip { if ($0 ~ "^" indent "}$") skip = 0; next }
    match($0, /^ *ATTRIBUTE "(seconds|cost\.[^"]*|note\.cost\.[^"]*)" \{$/) {
      indent = substr($0, 1, index($0, "A") - 1); skip = 1; next }
    { print }'
}
physics "$out/study.h5" >"$tmp/merged.txt"
physics "$tmp/one/study.h5" >"$tmp/one.txt"
grep -q 'ATTRIBUTE "temperature_mean"' "$tmp/merged.txt" || fail "the merged dump holds no cell attributes"
(cd "$out/cells" && ls) >"$tmp/merged.cells"
(cd "$tmp/one/cells" && ls) >"$tmp/one.cells"
diff -q "$tmp/one.cells" "$tmp/merged.cells" >/dev/null || {
  diff "$tmp/one.cells" "$tmp/merged.cells" >&2 || true; fail "the merged store's cell files differ from the one-process run's"; }
if ! cmp -s "$tmp/one.txt" "$tmp/merged.txt"; then
  diff "$tmp/one.txt" "$tmp/merged.txt" | head -n 20 >&2 || true
  fail "merged study.h5 differs from the one-process run's (above: one-process <, merged >)"
fi
log "equal: $(wc -l <"$tmp/one.cells") cells, $(wc -l <"$tmp/one.txt") lines of h5dump, timings aside"
