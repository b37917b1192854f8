#!/usr/bin/env bash
# `study convergence --refine` on a subset small enough for CI (case h — a case letter that is also a
# mesh name, a group beside the dataset h_along_S —, two thicknesses, h and h/2:
# 10 scenes), through the code path of the full study:
#   1. a first run (over 2 MPI ranks when MPIRUN is given) solves every scene, keeps each in DIR/scenes,
#      writes results.h5 and the report, and fails its checks (exit 1: two thicknesses give one Cauchy
#      difference, and h/4 is not run: "not established" is the honest verdict);
#   2. a second run (one process) solves nothing, and its results.h5 equals the first's but for timings;
#   3. a scene file removed and one altered: the third run solves exactly those two again;
#   4. a file in the store that thinlayer did not write: refused (exit 2, one line), the file untouched.
# usage: refinement_study_test.sh THINLAYER PYTHON COMPARE_SCRIPT [MPIRUN]
set -euo pipefail
thinlayer=$1 python=$2 compare=$3 mpirun=${4:-}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
study=(study convergence --cases h --rate-eps 1e-6,3.16227766e-7 --refine 1,2)

expect_status() {  # expected actual what
  if [ "$1" != "$2" ]; then
    echo "$3: exit status $2, expected $1"
    tail -30 "$dir/err.txt" "$dir/out.txt" 2>/dev/null || true
    exit 1
  fi
}
solved_count() { sed -n 's/.* \([0-9]*\) to solve .*/\1/p' "$dir/err.txt"; }

status=0
if [ -n "$mpirun" ]; then
  "$mpirun" --oversubscribe --allow-run-as-root -n 2 "$thinlayer" "${study[@]}" --out "$dir/one" >"$dir/out.txt" 2>"$dir/err.txt" || status=$?
else
  "$thinlayer" "${study[@]}" --out "$dir/one" >"$dir/out.txt" 2>"$dir/err.txt" || status=$?
fi
expect_status 1 "$status" "first run"
[ "$(solved_count)" = 10 ] || { echo "first run: $(solved_count) scenes to solve, expected 10"; exit 1; }
[ "$(ls "$dir/one/scenes" | grep -c '\.scene$')" = 10 ] || { echo "first run: the store does not hold 10 scenes"; exit 1; }
grep -q "(h) u_away .*h/4 not run: not established: " "$dir/out.txt" || { echo "first run: no verdict line for u_away"; exit 1; }
[ -f "$dir/one/report/index.html" ] || { echo "first run: no report"; exit 1; }

mkdir "$dir/two"
cp -r "$dir/one/scenes" "$dir/two/scenes"
status=0
"$thinlayer" "${study[@]}" --out "$dir/two" >"$dir/out.txt" 2>"$dir/err.txt" || status=$?
expect_status 1 "$status" "second run"
[ "$(solved_count)" = 0 ] || { echo "second run: $(solved_count) scenes solved again, expected 0"; exit 1; }
"$python" "$compare" "$dir/one/results.h5" "$dir/two/results.h5"

rm "$dir/two/scenes/h0.025-h-limit.scene"
printf 'x' >>"$dir/two/scenes/h0.025-h-layer-eps1e-06-plus.scene"
status=0
"$thinlayer" "${study[@]}" --out "$dir/two" >"$dir/out.txt" 2>"$dir/err.txt" || status=$?
expect_status 1 "$status" "third run"
[ "$(solved_count)" = 2 ] || { echo "third run: $(solved_count) scenes solved again, expected 2"; exit 1; }
grep -q "h0.025-h-layer-eps1e-06-plus.scene: its checksum does not match" "$dir/err.txt" ||
  { echo "third run: the altered scene file is not named"; exit 1; }
"$python" "$compare" "$dir/one/results.h5" "$dir/two/results.h5"

echo "my notes" >"$dir/two/scenes/h0.025-h-limit.scene"
status=0
"$thinlayer" "${study[@]}" --out "$dir/two" >"$dir/out.txt" 2>"$dir/err.txt" || status=$?
expect_status 2 "$status" "a foreign file in the store"
[ "$(cat "$dir/two/scenes/h0.025-h-limit.scene")" = "my notes" ] || { echo "the foreign file was touched"; exit 1; }
[ "$(wc -l <"$dir/err.txt")" = 1 ] || { echo "a foreign file in the store: not one line:"; cat "$dir/err.txt"; exit 1; }
echo "refinement study: first run, resume, damaged and foreign store files as expected"
