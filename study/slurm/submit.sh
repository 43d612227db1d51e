#!/usr/bin/env bash
# Submits a study to Slurm: a job array of N shards (`dpdrng study run CONFIG --shard k/N`, each into
# OUT/shard-k), then one job that waits for all of them (afterok), merges them into OUT and writes OUT/report/.
# Prints the two job ids. The job scripts are written to OUT/slurm/ (kept: they are what ran) and the jobs' logs
# go there too. Resubmitting the same command after a failure computes only the missing cells: each shard resumes
# its own directory and the merge copies only the cells OUT lacks.
# Assumes OUT, CONFIG and dpdrng are on a file system the compute nodes see at the same paths.
set -euo pipefail

usage() {
  cat <<'EOF'
Usage: study/slurm/submit.sh CONFIG OUT [options] [-- SBATCH_OPTION...]

Submits the study CONFIG as a Slurm job array of shards, each `dpdrng study run CONFIG --shard k/N
--out OUT/shard-k --threads $SLURM_CPUS_PER_TASK`, and a job that runs after all of them succeeded
(--dependency=afterok): `dpdrng study merge OUT/shard-* --out OUT` and `dpdrng study report OUT`.
Prints "shards JOBID" and "merge JOBID" on standard output. Rerun the same command after a failure:
only the missing cells are computed.

Options:
  --shards N          array tasks (default 4; at most the number of cells)
  --cpus-per-task C   cores per shard, cells run side by side (default 2)
  --time T            time limit of each shard (sbatch --time, default: the partition's)
  --partition P       partition of both jobs (default: the cluster's default)
  --dpdrng PATH       the dpdrng binary (default: dpdrng on PATH, else build/release/dpdrng)
  --dry-run           print the sbatch commands and job scripts, submit nothing
  -h, --help          this help
Anything after `--` is passed to both sbatch calls (e.g. -- --account=A --qos=Q).

Exit status: 0 submitted, 1 sbatch failed, 2 bad arguments.
EOF
}

die() { echo "submit.sh: $*" >&2; echo "(study/slurm/submit.sh --help for usage)" >&2; exit 2; }

repo=$(cd "$(dirname "$0")/../.." && pwd)
shards=4 cpus=2 time_limit="" partition="" dpdrng="" dry_run=0
positional=() extra=()
need_value() { (($1 >= 2)) || die "$2 needs a value"; }
while (($#)); do
  case $1 in
    -h|--help) usage; exit 0 ;;
    --shards) need_value $# "$1"; shards=$2; shift 2 ;;
    --shards=*) shards=${1#*=}; shift ;;
    --cpus-per-task) need_value $# "$1"; cpus=$2; shift 2 ;;
    --cpus-per-task=*) cpus=${1#*=}; shift ;;
    --time) need_value $# "$1"; time_limit=$2; shift 2 ;;
    --time=*) time_limit=${1#*=}; shift ;;
    --partition) need_value $# "$1"; partition=$2; shift 2 ;;
    --partition=*) partition=${1#*=}; shift ;;
    --dpdrng) need_value $# "$1"; dpdrng=$2; shift 2 ;;
    --dpdrng=*) dpdrng=${1#*=}; shift ;;
    --dry-run) dry_run=1; shift ;;
    --) shift; extra=("$@"); break ;;
    -*) die "unknown option: $1" ;;
    *) positional+=("$1"); shift ;;
  esac
done
((${#positional[@]} == 2)) || die "expected CONFIG and OUT, got ${#positional[@]} argument(s)"
config=${positional[0]} out=${positional[1]}
[[ $shards =~ ^[1-9][0-9]*$ ]] || die "--shards must be a positive integer, got '$shards'"
[[ $cpus =~ ^[1-9][0-9]*$ ]] || die "--cpus-per-task must be a positive integer, got '$cpus'"
[[ -f $config && -r $config ]] || die "CONFIG '$config' is not a readable file"
[[ -n $out ]] || die "OUT is empty"
[[ -e $out && ! -d $out ]] && die "OUT '$out' exists and is not a directory"

if [[ -z $dpdrng ]]; then
  if command -v dpdrng >/dev/null; then dpdrng=$(command -v dpdrng)
  elif [[ -x $repo/build/release/dpdrng ]]; then dpdrng=$repo/build/release/dpdrng
  else die "no dpdrng on PATH nor at $repo/build/release/dpdrng: give --dpdrng PATH"; fi
fi
[[ -f $dpdrng && -x $dpdrng ]] || die "--dpdrng '$dpdrng' is not an executable file"
# Absolute paths: the jobs start in another working directory, possibly on another node.
dpdrng=$(realpath "$dpdrng")
config=$(realpath "$config")
out=$(realpath -m "$out")

# Refuse a bad config here (exit 2) rather than in every array task after a wait in the queue.
"$dpdrng" --validate-only study run "$config" --out "$out/shard-1" --shard "1/$shards" \
  || die "dpdrng refuses the config or arguments (see above)"
cells=$("$dpdrng" study cells "$config" | grep -c .) || die "dpdrng study cells '$config' failed"
((cells > 0)) || die "the config has no cells"
# An array task with no cell would only cost a slot in the queue.
if ((shards > cells)); then
  echo "submit.sh: $cells cells: --shards $shards lowered to $cells" >&2
  shards=$cells
fi
if ((dry_run == 0)); then
  command -v sbatch >/dev/null || { echo "submit.sh: sbatch not found (is Slurm installed?)" >&2; exit 1; }
fi

logs=$out/slurm
mkdir -p "$logs" || die "cannot create '$logs'"
q() { printf '%q' "$1"; }
# Written to files rather than --wrap: the scripts stay beside the results and can be rerun or read.
cat >"$logs/shard.sh" <<EOF
#!/usr/bin/env bash
# Array task k of $shards: the cells k, k + $shards, ... of the study (resumes OUT/shard-k if it exists).
set -euo pipefail
exec $(q "$dpdrng") study run $(q "$config") --shard "\${SLURM_ARRAY_TASK_ID}/$shards" \\
     --out $(q "$out")/shard-"\${SLURM_ARRAY_TASK_ID}" --threads "\${SLURM_CPUS_PER_TASK:-1}"
EOF
cat >"$logs/merge.sh" <<EOF
#!/usr/bin/env bash
# After every shard succeeded: their cells into OUT (only those it lacks), study.h5, then the report. Every
# shard-* directory, also those of an earlier submission with another --shards: their cells count too.
set -euo pipefail
shopt -s nullglob
dirs=($(q "$out")/shard-*/)
$(q "$dpdrng") study merge "\${dirs[@]}" --out $(q "$out")
exec $(q "$dpdrng") study report $(q "$out")
EOF
chmod +x "$logs/shard.sh" "$logs/merge.sh"

name=$(basename "$out")
common=(--parsable --chdir="$out")
[[ -n $partition ]] && common+=(--partition="$partition")
shard_cmd=(sbatch "${common[@]}" --job-name="$name-shards" --array="1-$shards" --cpus-per-task="$cpus"
           --output="$logs/shard-%A_%a.log")
[[ -n $time_limit ]] && shard_cmd+=(--time="$time_limit")
shard_cmd+=("${extra[@]}" "$logs/shard.sh")
merge_cmd=(sbatch "${common[@]}" --job-name="$name-merge" --cpus-per-task=1 --output="$logs/merge-%j.log")

if ((dry_run)); then
  printf '%q ' "${shard_cmd[@]}"; echo
  printf '%q ' "${merge_cmd[@]}" "--dependency=afterok:<shards>" "${extra[@]}" "$logs/merge.sh"; echo
  cat "$logs/shard.sh" "$logs/merge.sh"
  exit 0
fi
# --parsable prints "jobid" or "jobid;cluster".
shard_id=$("${shard_cmd[@]}") || { echo "submit.sh: sbatch of the shards failed" >&2; exit 1; }
shard_id=${shard_id%%;*}
merge_id=$("${merge_cmd[@]}" --dependency="afterok:$shard_id" "${extra[@]}" "$logs/merge.sh") || {
  echo "submit.sh: sbatch of the merge job failed; cancelling the shards ($shard_id)" >&2
  scancel "$shard_id" || true
  exit 1
}
merge_id=${merge_id%%;*}
echo "shards $shard_id"
echo "merge $merge_id"
echo "submit.sh: $cells cells in $shards shards; logs and job scripts in $logs" >&2
