// Operands for which LLVM leaves an op undefined (docs/Model.md, "Other
// rules"; --sim-define-edge-cases): integer division and remainder by a
// parameter @d (0 and -1 among the values the test sets), shifts by a
// parameter @s (the width and more among them), float-to-integer
// conversions of a parameter @x plus the item (NaN, infinities, values past
// the integer types' ends) and an scf.for whose step is a parameter @step
// (0 and negative among them). The dividend is the item minus 4, and the
// smallest i32 at item 0 (whose quotient by -1 does not fit). Every result
// is exact in f64, so @R holds them as they are.
sim.simulation @edge_cases range(9) dt(1.0 : f64) max_steps(1) {
  sim.param @d = 3 : i32
  sim.param @s = 2 : i32
  sim.param @x = 1.5 : f32
  sim.param @step = 1 : index

  sim.buffer @R : vector<12xf64> init {
  ^bb0(%i: index):
    %z = arith.constant dense<0.0> : vector<12xf64>
    sim.yield %z : vector<12xf64>
  }
  sim.component @Edge writes(@R) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %i32 = arith.index_cast %i : index to i32
    %c0 = arith.constant 0 : i32
    %c4 = arith.constant 4 : i32
    %min = arith.constant -2147483648 : i32
    %off = arith.subi %i32, %c4 : i32
    %first = arith.cmpi eq, %i32, %c0 : i32
    %a = arith.select %first, %min, %off : i32
    %d = sim.get_param @d : i32
    %q = arith.divsi %a, %d : i32
    %r = arith.remsi %a, %d : i32
    %qu = arith.divui %a, %d : i32
    %ru = arith.remui %a, %d : i32
    %fl = arith.floordivsi %a, %d : i32
    %ce = arith.ceildivsi %a, %d : i32
    %s = sim.get_param @s : i32
    %one = arith.constant 1 : i32
    %shl = arith.shli %one, %s : i32
    %shr = arith.shrsi %a, %s : i32
    %shru = arith.shrui %a, %s : i32
    %x = sim.get_param @x : f32
    %fi = arith.sitofp %i32 : i32 to f32
    %xi = arith.addf %x, %fi : f32
    %si = arith.fptosi %xi : f32 to i32
    %ui = arith.fptoui %xi : f32 to i32
    %step = sim.get_param @step : index
    %lo = arith.constant 0 : index
    %hi = arith.constant 4 : index
    %count = scf.for %k = %lo to %hi step %step iter_args(%c = %c0) -> i32 {
      %next = arith.addi %c, %one : i32
      scf.yield %next : i32
    }
    %vals = arith.constant dense<0.0> : vector<12xf64>
    %f0 = arith.sitofp %q : i32 to f64
    %f1 = arith.sitofp %r : i32 to f64
    %f2 = arith.uitofp %qu : i32 to f64
    %f3 = arith.uitofp %ru : i32 to f64
    %f4 = arith.sitofp %fl : i32 to f64
    %f5 = arith.sitofp %ce : i32 to f64
    %f6 = arith.uitofp %shl : i32 to f64
    %f7 = arith.sitofp %shr : i32 to f64
    %f8 = arith.uitofp %shru : i32 to f64
    %f9 = arith.sitofp %si : i32 to f64
    %f10 = arith.uitofp %ui : i32 to f64
    %f11 = arith.sitofp %count : i32 to f64
    %v0 = vector.insert %f0, %vals [0] : f64 into vector<12xf64>
    %v1 = vector.insert %f1, %v0 [1] : f64 into vector<12xf64>
    %v2 = vector.insert %f2, %v1 [2] : f64 into vector<12xf64>
    %v3 = vector.insert %f3, %v2 [3] : f64 into vector<12xf64>
    %v4 = vector.insert %f4, %v3 [4] : f64 into vector<12xf64>
    %v5 = vector.insert %f5, %v4 [5] : f64 into vector<12xf64>
    %v6 = vector.insert %f6, %v5 [6] : f64 into vector<12xf64>
    %v7 = vector.insert %f7, %v6 [7] : f64 into vector<12xf64>
    %v8 = vector.insert %f8, %v7 [8] : f64 into vector<12xf64>
    %v9 = vector.insert %f9, %v8 [9] : f64 into vector<12xf64>
    %v10 = vector.insert %f10, %v9 [10] : f64 into vector<12xf64>
    %v11 = vector.insert %f11, %v10 [11] : f64 into vector<12xf64>
    sim.yield %v11 : vector<12xf64>
  }
  sim.observe [@R]
}
