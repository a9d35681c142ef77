#!/usr/bin/env bash
# CPU nanoseconds per sample of the render kernel for two builds of vissweep, alternating:
# (cpu(render --spp HI) - cpu(render --spp LO)) / (HI - LO) / pixels, LP_NUM_THREADS=1. CPU time
# leaves out the time a process waits for a core, so two builds compare fairly on a loaded machine;
# setup (volume, sweeps, pipeline compiles) cancels in the difference.
# usage: Benchmarks/cpu_ab.sh OLD_VISSWEEP NEW_VISSWEEP REPEATS SCENE STRATEGY [SIZE] [LO] [HI]
#   OLD_VISSWEEP may be "env LD_LIBRARY_PATH=old/lib old/bin/vissweep" (a copied build).
set -euo pipefail
old=$1; new=$2; n=$3; scene=$4; strategy=$5; size=${6:-128}; lo=${7:-4}; hi=${8:-260}
cpu() { /usr/bin/time -f "%U %S" env LP_NUM_THREADS=1 "$@" 2>&1 >/dev/null | tail -1 | awk '{print $1 + $2}'; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for _ in $(seq "$n"); do
  for side in old new; do
    bin=$old; [ "$side" = new ] && bin=$new
    # shellcheck disable=SC2086
    a=$(cpu xvfb-run -a $bin render "$scene" --strategy "$strategy" --width "$size" --height "$size" --spp "$lo" -o "$out/a.exr")
    # shellcheck disable=SC2086
    b=$(cpu xvfb-run -a $bin render "$scene" --strategy "$strategy" --width "$size" --height "$size" --spp "$hi" -o "$out/b.exr")
    echo "$side $strategy $(echo "$a $b" | awk -v n=$((hi - lo)) -v p=$((size * size)) '{printf "%.1f", 1e9 * ($2 - $1) / n / p}')"
  done
done
