#!/usr/bin/env bash
# SPEC §4 and §6: Ctrl-C (SIGINT to mpirun) during a study spread over 2 ranks stops every rank
# promptly and leaves no partial output: no temporary file, the previous results.h5 untouched.
# usage: mpi_interrupt_test.sh THINLAYER MPIRUN
# The run must outlast the interrupt: with one case it could finish (and replace results.h5)
# between the temporary file appearing and the signal, so it solves all nine cases.
set -euo pipefail
thinlayer=$1 mpirun=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
# The previous result: a file thinlayer wrote.
"$thinlayer" solve --case bar --row 1 --out "$dir/results.h5" >/dev/null
before=$(md5sum <"$dir/results.h5")

"$mpirun" --oversubscribe --allow-run-as-root -n 2 "$thinlayer" study convergence --cases abcdefghi \
  --eps 1e-2,5e-3,1e-3 --quiet --out "$dir" >"$dir/run.log" 2>&1 &
launcher=$!
# Interrupt once the run is under way: its temporary results file exists.
for _ in $(seq 200); do
  compgen -G "$dir/results.h5.tmp.*" >/dev/null && break
  sleep 0.05
done
compgen -G "$dir/results.h5.tmp.*" >/dev/null || { echo "the run never started writing"; exit 1; }
kill -INT "$launcher"
for _ in $(seq 200); do
  kill -0 "$launcher" 2>/dev/null || break
  sleep 0.05
done
if kill -0 "$launcher" 2>/dev/null; then
  echo "mpirun still running 10 s after SIGINT"
  kill -KILL "$launcher"
  exit 1
fi
status=0
wait "$launcher" || status=$?
[ "$status" -ne 0 ] || { echo "an interrupted run exited 0"; exit 1; }
if compgen -G "$dir/results.h5.tmp.*" >/dev/null; then echo "temporary file left behind"; exit 1; fi
[ "$(md5sum <"$dir/results.h5")" = "$before" ] || { echo "the previous results.h5 was changed"; exit 1; }
echo "interrupted (exit $status), nothing left behind"
