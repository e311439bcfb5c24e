// RUN: sim-opt %s --sim-vectorize-lanes=width=3 --verify-diagnostics -o /dev/null

// A width that is not a power of two from 2 to 64 is refused. The file's
// top module has no location of its own ("file:0:0"), so the error is at
// its first operation.

// expected-error @below {{--sim-vectorize-lanes: width must be a power of two from 2 to 64, not 3}}
func.func @kernel() {
  return
}
