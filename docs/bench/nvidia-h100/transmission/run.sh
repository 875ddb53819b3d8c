#!/usr/bin/env bash
# Issue 65's transmission record (nvidia-h100-x1): `run.sh STEP...`, each step one of
#   before, after   ../material-extensions/ab.sweep.json (atrium and Sponza, 1,048,576 lights) with
#                   the binary before the material extensions (.devbin-before, 921f644) or this one (.devbin)
#   cost            cost.sweep.json: the transmission files as they are and without transmission
#   accuracy        accuracy.sweep.json: every method against naive on them
# with .devbin and .devbin-before (tools/pack-for-gpu's output), .gl/ (Debian's GL dispatch, Embree
# and TBB packages) and .gpushared/ (../shared's corpus/amd/ and the khronos TransmissionTest,
# TransmissionRoughnessTest, AttenuationTest, ToyCar, LightsPunctualLamp and IridescenceSuzanne
# folders, each transmissive file with a -notransmission copy: KHR_materials_transmission and
# volume stripped from its materials) carried. A step's name gains a suffix per repeat (the SM
# clock dips on a call's first points). Every file lands in $OUT/transmission.tgz after each step.
set -u
D=docs/bench/nvidia-h100/transmission
R=/tmp/results/transmission
mkdir -p $R
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv >> $R/gpu.txt
pack() { (cd /tmp/results && tar czf $OUT/transmission.tgz transmission); }
run() {  # binary folder, sweep file, name, seconds
  local name=$3 n=1
  while [ -e $R/$name.log ]; do n=$((n + 1)); name=$3-$n; done
  LD_LIBRARY_PATH=$1/lib timeout $4 $1/manylights bench --sweep $2 --backend egl --out $R --name $name > $R/$name.log 2>&1
  echo "$name rc $? $(date +%T) $(nvidia-smi --query-gpu=clocks.sm --format=csv,noheader)" >> $R/steps.txt
  pack
}
for step in "$@"; do
  case $step in
    before) run .devbin-before docs/bench/nvidia-h100/material-extensions/ab.sweep.json before 90 ;;
    after) run .devbin docs/bench/nvidia-h100/material-extensions/ab.sweep.json after 90 ;;
    cost) run .devbin $D/cost.sweep.json cost 200 ;;
    accuracy) run .devbin $D/accuracy.sweep.json accuracy 200 ;;
    *) echo "run.sh: unknown step '$step'" >&2; exit 2 ;;
  esac
done
