#!/usr/bin/env bash
# Runs the libFuzzer harnesses of a SIMCAP_FUZZ build: each for SECONDS, niced, with memory, time
# and allocation limits, from its seed corpus, regressions and dictionary. New inputs go to
# BUILD/fuzz-corpus/<target>/ (kept between runs), crashes to tests/fuzz/findings/<target>/ with
# a .txt file of the commands that reproduce them. Appends each run's statistics to
# BUILD/fuzz-stats.tsv and prints the totals; exits 1 when there are findings.
#   scripts/fuzz.sh BUILD SECONDS [TARGET...]     e.g. scripts/fuzz.sh build-fuzz 30 bvh scene
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:?usage: scripts/fuzz.sh BUILD SECONDS [TARGET...]}
seconds=${2:?usage: scripts/fuzz.sh BUILD SECONDS [TARGET...]}
shift 2
fuzz=tests/fuzz
if [ $# -eq 0 ]; then
  set -- $(ls "$build/$fuzz" | sed -n 's/^fuzz_\([a-z0-9_]*\)$/\1/p' | grep -v '^replay_')
fi
stats="$build/fuzz-stats.tsv"
[ -f "$stats" ] || printf 'date\ttarget\tseconds\texecutions\tcoverage\tfeatures\tcorpus\n' >"$stats"
scratch=$(mktemp -d "${FUZZ_TMPDIR:-/dev/shm}/simcap-fuzz.XXXXXX" 2>/dev/null || mktemp -d)
trap 'rm -rf "$scratch"' EXIT

for target in "$@"; do
  harness="$build/$fuzz/fuzz_$target"
  [ -x "$harness" ] || { echo "fuzz: no harness $harness" >&2; exit 2; }
  corpus="$build/fuzz-corpus/$target" findings="$fuzz/findings/$target"
  mkdir -p "$corpus" "$findings" "$fuzz/regressions/$target"
  dict=()
  [ -f "$fuzz/dict/$target.dict" ] && dict=(-dict="$fuzz/dict/$target.dict")
  log="$build/fuzz-logs/$target.log"
  mkdir -p "$(dirname "$log")"
  echo "fuzz: $target for ${seconds}s" >&2
  # A finding stops the run with a non-zero status; the loop goes on to the next target. No
  # allocation may exceed 2 GiB; resident memory may reach 4 GiB, because the harnesses that link
  # OpenImageIO start at 2.2 GiB under ASan (its plugins load, the DICOM dictionary among them).
  # The frame-pointer unwinder (ASan's default) records every allocation's stack: the slow one
  # would make every harness 3 to 5 times slower, and lsan.supp matches clang's stacks without it.
  # Niced in a session of its own: where the kernel groups processes by session (autogroup), a
  # nice value only ranks a process within its session, and a niced fuzzer would still take a
  # whole core from the builds of other sessions; the session's own group is niced too.
  TMPDIR="$scratch" LSAN_OPTIONS=suppressions=$fuzz/lsan.supp setsid -w bash -c \
    'echo 19 >/proc/self/autogroup 2>/dev/null; exec nice -n 19 "$@"' fuzz "$harness" "${dict[@]}" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=4096 -malloc_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$findings/" "$corpus" "$fuzz/corpus/$target" "$fuzz/regressions/$target" \
    >"$log" 2>&1 || true
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  last=$(grep -E '^#[0-9]+' "$log" | tail -1 || true)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$(date -u +%FT%TZ)" "$target" "$seconds" "${execs:-0}" \
    "${cov:-?}" "${ft:-?}" "$(ls "$corpus" | wc -l)" >>"$stats"
  for f in "$findings"/*; do
    [ -f "$f" ] && [ "${f%.txt}" = "$f" ] && [ "${f%.log}" = "$f" ] && [ ! -f "$f.txt" ] || continue
    {
      echo "# $(grep -m1 -E 'ERROR|runtime error|terminate|Assert' "$log" || echo 'see the log')"
      echo "# reproduce (clang, sanitized):"
      echo "$harness $f"
      echo "# minimize, then keep it as a regression input (replayed by ctest with gcc):"
      echo "$harness -minimize_crash=1 -max_total_time=60 -exact_artifact_path=$fuzz/regressions/$target/NAME $f"
      echo "build/$fuzz/fuzz_replay_$target $f"
    } >"$f.txt"
    cp "$log" "$f.log"
  done
done

echo
printf '%-24s %14s %14s %8s %8s\n' target 'this run' 'all runs' cov ft
status=0
for target in "$@"; do
  awk -F'\t' -v t="$target" '$2 == t { n += $4; last = $4; cov = $5; ft = $6 }
    END { printf "%-24s %14d %14d %8s %8s\n", t, last, n, cov, ft }' "$stats"
  if ls "$fuzz/findings/$target"/*.txt >/dev/null 2>&1; then
    echo "  findings: $(ls "$fuzz/findings/$target"/*.txt | sed 's/\.txt$//' | tr '\n' ' ')"
    status=1
  fi
done
exit $status
