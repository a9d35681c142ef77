#!/usr/bin/env bash
# The plugin's GUI test: ParaView's GUI (under the display given, e.g. xvfb-run) runs
# gui_refinement.py, which renders a VisSweep volume once at 4 of 12 samples per pixel; the plugin's
# refinement timer (ParaView/Plugin/Client/pqVisSweepRefinement.h) must then render the still view
# until it logs "converged at 12 samples per pixel", within 240 s (the GUI's start alone took 80 s on
# the 2-core machine under a load of 7). Twice: in the builtin session,
# then as the client of a pvserver (remote rendering: the server renders, the client's timer reads
# the server's samples). Run as root: the GUI runs in scripts/paraview-check.sh's mount namespace,
# where ParaView's Python modules lie over Debian's VTK 9.1 ones.
#   run-gui-test.sh ROOT PLUGIN OUTDIR [PV_ROOT]
set -euo pipefail
root="$1"; plugin="$2"; out="$3"; pvroot="${4:-$root/build-pv-root}"
rm -rf "$out"; mkdir -p "$out"
export VS_PLUGIN="$plugin" VS_VOLUME="$root/Examples/Scenes/tiny_sphere.vti"

# Ends a process this script started: SIGTERM, then SIGKILL if it is still there after 15 s
# (a pvserver whose client went away was seen to hang on SIGTERM).
stop() {
  kill "$1" 2>/dev/null || true
  for _ in $(seq 30); do kill -0 "$1" 2>/dev/null || break; sleep 0.5; done
  kill -9 "$1" 2>/dev/null || true
  wait "$1" 2>/dev/null || true
}

# Runs the GUI (its arguments after the log's name) until the timer logs convergence at 12 spp.
# --dr: no user settings, so no welcome dialog (as the client of a server it opened during the
# connection and its modal loop kept the script from ever running).
gui() {
  local log="$1" what="$2"; shift 2
  unshare -m "$root/scripts/paraview-check.sh" --inside \
    paraview --dr --verbosity=INFO --script="$root/ParaView/Testing/gui_refinement.py" "$@" > "$log" 2>&1 &
  local pid=$! ok=1
  for _ in $(seq 240); do
    if grep -q 'VisSweep: the view is converged at 12 samples per pixel' "$log"; then ok=0; break; fi
    if ! kill -0 $pid 2>/dev/null; then break; fi
    sleep 1
  done
  stop $pid
  grep -E "after the script's one render|VisSweep: the view" "$log" || true
  if [ $ok = 0 ]; then
    echo "ok   the GUI ($what) refined the still view to MaximumSamples (12) by itself"
  else
    echo "FAIL the GUI ($what) did not refine the still view to 12 samples per pixel within 240 s:"; tail -20 "$log"
  fi
  return $ok
}

status=0
gui "$out/gui.log" "builtin session" || status=1

# The client of a pvserver on this machine (remote rendering).
port="$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("localhost", 0)); print(s.getsockname()[1])')"
env PYTHONPATH="$pvroot/usr/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}" \
  pvserver --server-port="$port" > "$out/pvserver.out" 2> "$out/pvserver.err" &
server=$!
for _ in $(seq 120); do
  if grep -q "Accepting connection" "$out/pvserver.out" || ! kill -0 $server 2>/dev/null; then break; fi
  sleep 0.5
done
VS_REMOTE=1 gui "$out/gui-remote.log" "client of a pvserver" --server-url="cs://localhost:$port" || status=1
if [ $status = 0 ] && ! grep -q 'converged at 12 samples per pixel (remote session)' "$out/gui-remote.log"; then
  echo "FAIL the client's timer did not run in a remote session"; status=1
fi
stop $server
if [ $status != 0 ]; then tail -n 5 "$out/pvserver.out" "$out/pvserver.err"; fi
exit $status
