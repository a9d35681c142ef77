#!/usr/bin/env bash
# The VisSweep plugin under MPI: pvbatch_mpi.py renders Examples/Scenes/tiny_sphere.vti with one
# pvbatch process (seeds 1 and 2), then with `mpiexec -n 2 pvbatch --mpi`, where ParaView gives each
# process half of the volume; the two processes' image must be the one process's within its noise,
# with all 16 samples per pixel after one frame of 8 per process (pvbatch_mpi.py says how). Checks
# that the environment not drawn under MPI is a warning on stderr. Then (as root) a pvpython client
# of `mpiexec -n 2 pvserver` (pvpython_client.py). Needs a display (xvfb-run).
#   run-mpi-test.sh ROOT PV_ROOT PLUGIN OUTDIR
set -euo pipefail
root="$1"; pvroot="$2"; plugin="$3"; out="$4"
rm -rf "$out"; mkdir -p "$out"
export PYTHONPATH="$pvroot/usr/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
# Open MPI on one machine, as root (the test runs as root in CI), without cross-memory attach
# (refused in containers) and with more processes than cores if need be.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
  OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_rmaps_base_oversubscribe=1
script="$root/ParaView/Testing/pvbatch_mpi.py"
volume="$root/Examples/Scenes/tiny_sphere.vti"

status=0
timeout 300 pvbatch "$script" "$plugin" "$volume" "$out" single > "$out/single.out" 2> "$out/single.err" || status=$?
cat "$out/single.out"
if [ "$(cat "$out/result-single.txt" 2>/dev/null)" != "0 failure(s)" ]; then
  echo "FAIL the one-process run (status $status):"; tail -20 "$out/single.err"; exit 1
fi
status=0
timeout 300 mpiexec -n 2 pvbatch --mpi "$script" "$plugin" "$volume" "$out" mpi > "$out/mpi.out" 2> "$out/mpi.err" || status=$?
cat "$out/mpi.out"
if [ "$(cat "$out/result-mpi.txt" 2>/dev/null)" != "0 failure(s)" ]; then
  echo "FAIL the two-process run (status $status): $(cat "$out/result-mpi.txt" 2>/dev/null || echo 'no result')"
  tail -30 "$out/mpi.err"; exit 1
fi
if grep -q 'EnvironmentVisible: with 2 processes the environment lights the volume but is not drawn' "$out/mpi.err"; then
  echo "ok   the environment not drawn under MPI is a warning on stderr"
else
  echo "FAIL no warning that the environment is not drawn under MPI"; tail -30 "$out/mpi.err"; exit 1
fi
# A pvpython client of `mpiexec -n 2 pvserver` (client-server with MPI): the image is made by the two
# server processes, and the client reads their samples (pvpython_client.py). Root only: pvpython runs
# in scripts/paraview-check.sh's mount namespace, where ParaView's Python modules lie over Debian's.
if [ "$(id -u)" = 0 ]; then
  port="$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("localhost", 0)); print(s.getsockname()[1])')"
  timeout 300 mpiexec -n 2 pvserver --mpi --server-port="$port" > "$out/pvserver.out" 2> "$out/pvserver.err" &
  server=$!
  for _ in $(seq 120); do
    if grep -q "Accepting connection" "$out/pvserver.out" || ! kill -0 $server 2>/dev/null; then break; fi
    sleep 0.5
  done
  status=0
  timeout 300 unshare -m "$root/scripts/paraview-check.sh" --inside pvpython \
    "$root/ParaView/Testing/pvpython_client.py" "$plugin" "$volume" "$out" "$port" > "$out/client.out" 2> "$out/client.err" || status=$?
  for _ in $(seq 60); do kill -0 $server 2>/dev/null || break; sleep 0.5; done
  kill $server 2>/dev/null || true
  wait $server 2>/dev/null || true
  cat "$out/client.out"
  if [ "$(cat "$out/result-client.txt" 2>/dev/null)" != "0 failure(s)" ]; then
    echo "FAIL the client of two pvserver processes (status $status):"; tail -20 "$out/client.err" "$out/pvserver.out" "$out/pvserver.err"; exit 1
  fi
else
  echo "skip the client of mpiexec -n 2 pvserver (root only)"
fi
read -r _ t1 _ < "$out/timing-single.txt"; read -r _ t2 _ < "$out/timing-mpi.txt"
/usr/bin/python3 -c "import sys; t1, t2 = float(sys.argv[1]), float(sys.argv[2]); print('samples per second, 2 processes / 1: %.2f (%.3f s per frame of 16 spp, %.3f s per frame of 2 x 16)' % (2 * t1 / t2, t1, t2))" "$t1" "$t2"
exit 0
