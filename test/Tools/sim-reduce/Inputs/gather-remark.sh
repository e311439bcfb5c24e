#!/bin/sh
# The interestingness test of reduce-scene.mlir. As with mlir-reduce, a
# candidate is interesting when the script exits with a status other than 0:
# here while sim-opt's sub-step legality still remarks that a component
# reads its own buffer through a gather. $SIM_OPT is the sim-opt to run, $1
# the candidate scene.
if "$SIM_OPT" "$1" --sim-substep-legality -o - 2>&1 |
  grep -q "reads @U through a gather"; then
  exit 1
fi
exit 0
