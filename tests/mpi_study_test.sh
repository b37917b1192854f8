#!/usr/bin/env bash
# SPEC §6: a study spread over 2 MPI ranks writes the same DIR/results.h5 as one process,
# dataset by dataset and attribute by attribute (timings excepted: tests/compare_results.py),
# records the ranks it used, and ends with the same exit status.
# usage: mpi_study_test.sh THINLAYER MPIRUN PYTHON COMPARE_SCRIPT STUDY [STUDY OPTIONS...]
set -euo pipefail
thinlayer=$1 mpirun=$2 python=$3 compare=$4
shift 4
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

one=0
"$thinlayer" study "$@" --quiet --out "$dir/one" >"$dir/one.txt" 2>&1 || one=$?
two=0
"$mpirun" --oversubscribe --allow-run-as-root -n 2 "$thinlayer" study "$@" --quiet --out "$dir/two" \
  >"$dir/two.txt" 2>&1 || two=$?
if [ "$one" -gt 1 ] || [ "$one" != "$two" ]; then
  echo "exit status: one process $one, two ranks $two"
  tail -20 "$dir/one.txt" "$dir/two.txt"
  exit 1
fi
"$python" -c "import h5py, sys; r = h5py.File(sys.argv[1])['/'].attrs['ranks']; sys.exit(0 if r == 2 else f'ranks = {r}')" \
  "$dir/two/results.h5"
"$python" "$compare" "$dir/one/results.h5" "$dir/two/results.h5"
