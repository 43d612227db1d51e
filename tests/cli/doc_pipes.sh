#!/usr/bin/env bash
# Runs the dpdrng commands a document shows: in every fenced ```sh block of each FILE.md, each line that starts
# with `dpdrng ` or `cc ` (a plug-in built for the lines after it; after an optional `$ `; a line ending in `\`
# goes on on the next), except the lines that end with `# not run` (too long for a test, or needing what a test
# machine lacks). Each runs under bash with `set -o pipefail`, the build's dpdrng first on PATH, in a scratch
# directory of its document (so a later line may read what an earlier one wrote) where the source tree's study/,
# examples/, include/ and tools/ are linked (so that `study/ci.toml` names the committed config and a plug-in
# finds dpdrng/plugin.h), and must exit 0 within 300 s.
# Usage: doc_pipes.sh DPDRNG SOURCE_DIR SCRATCH_DIR FILE.md... (FILE relative to SOURCE_DIR or absolute)
# Prints "FAIL (exit N): <command>" for each failure and a summary line; exits 1 if any command failed.
set -uo pipefail
bin=$(realpath "$1") source=$(realpath "$2") scratch=$3
shift 3
export PATH="$(dirname "$bin"):$PATH"
rm -rf "$scratch"
mkdir -p "$scratch"

# The commands of one markdown file, one a line (continuations joined).
commands_of() {
  awk '
    /^```/ { if (inside) { inside = 0 } else if ($0 ~ /^```sh[[:space:]]*$/) { inside = 1 }; next }
    !inside { next }
    pending != "" { pending = pending "\n" $0; if ($0 !~ /\\$/) { print_cmd(pending); pending = "" }; next }
    {
      line = $0
      sub(/^\$ /, "", line)
      if (line !~ /^(dpdrng|cc) /) next
      if (line ~ /\\$/) { pending = line; next }
      print_cmd(line)
    }
    function print_cmd(c) {
      if (c ~ /#[[:space:]]*not run[[:space:]]*$/) { skipped++; return }
      gsub(/\\\n/, " ", c)
      print c
    }
    END { printf "%d\n", skipped > "/dev/stderr" }
  ' "$1"
}

ran=0 failed=0 skipped=0
for doc in "$@"; do
  [[ $doc == /* ]] || doc="$source/$doc"
  [[ -f $doc ]] || { echo "FAIL: no such document: $doc"; failed=$((failed + 1)); continue; }
  dir="$scratch/$(basename "$doc" .md)"
  mkdir -p "$dir"
  for d in study examples include tools; do ln -s "$source/$d" "$dir/$d"; done
  mapfile -t cmds < <(commands_of "$doc" 2>"$dir/.skipped")
  skipped=$((skipped + $(cat "$dir/.skipped")))
  for cmd in "${cmds[@]}"; do
    ran=$((ran + 1))
    (cd "$dir" && timeout 300 bash -c "set -o pipefail; $cmd" >"$dir/.out" 2>"$dir/.err")
    rc=$?
    if ((rc == 0)); then
      echo "ok: $cmd ($(basename "$doc"))"
    else
      failed=$((failed + 1))
      echo "FAIL (exit $rc): $cmd ($(basename "$doc")): $(head -c 400 "$dir/.err")"
    fi
  done
done
echo "doc pipes: $failed of $ran commands failed, $skipped marked '# not run'"
((failed == 0))
