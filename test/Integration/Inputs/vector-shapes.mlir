// n-D vector shapes in a component body, for vector-shapes.test: a
// broadcast to vector<3x4xi32>, vector.shape_cast to 1-D, a mask made at
// run time (vector.create_mask, 1-D and 2-D), a constant one
// (vector.constant_mask) and an inclusive vector.scan. The GPU's lowering and the CPU's had no pattern
// for these without another high-level vector op in the body
// (--sim-lower-vector-ops). Integer arithmetic, so the values are exact:
// with x = A[i], row = (x, x+1, x+2, x+3), im = i % 4 and ir = i % 3, A[i]
// becomes (4 sum(row) + sum(row[:im]) + 2 sum(row[:3]) + ir sum(row[:im]))
// mod 1000.
sim.simulation @vector_shapes range(37) dt(1.0e-3 : f32) max_steps(4) {
  sim.buffer @A : f32 init {
  ^bb0(%i: index):
    %v = arith.index_cast %i : index to i32
    %f = arith.sitofp %v : i32 to f32
    sim.yield %f : f32
  }
  sim.component @W writes(@A) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %xf = sim.read @A[%i] : f32
    %x = arith.fptosi %xf : f32 to i32
    %v = vector.broadcast %x : i32 to vector<4xi32>
    %k = vector.step : vector<4xindex>
    %ki = arith.index_cast %k : vector<4xindex> to vector<4xi32>
    %row = arith.addi %v, %ki : vector<4xi32>
    %m2 = vector.broadcast %row : vector<4xi32> to vector<3x4xi32>
    %sc = vector.shape_cast %m2 : vector<3x4xi32> to vector<12xi32>
    %s1 = vector.reduction <add>, %sc : vector<12xi32> into i32
    %c4 = arith.constant 4 : index
    %im = arith.remui %i, %c4 : index
    %cm = vector.create_mask %im : vector<4xi1>
    %z4 = arith.constant dense<0> : vector<4xi32>
    %sel = arith.select %cm, %row, %z4 : vector<4xi1>, vector<4xi32>
    %s2 = vector.reduction <add>, %sel : vector<4xi32> into i32
    %km = vector.constant_mask [2, 3] : vector<3x4xi1>
    %z34 = arith.constant dense<0> : vector<3x4xi32>
    %sel2 = arith.select %km, %m2, %z34 : vector<3x4xi1>, vector<3x4xi32>
    %f2 = vector.shape_cast %sel2 : vector<3x4xi32> to vector<12xi32>
    %s3 = vector.reduction <add>, %f2 : vector<12xi32> into i32
    %c3 = arith.constant 3 : index
    %ir = arith.remui %i, %c3 : index
    %dm = vector.create_mask %ir, %im : vector<3x4xi1>
    %sel3 = arith.select %dm, %m2, %z34 : vector<3x4xi1>, vector<3x4xi32>
    %f3 = vector.shape_cast %sel3 : vector<3x4xi32> to vector<12xi32>
    %s4 = vector.reduction <add>, %f3 : vector<12xi32> into i32
    %z0 = arith.constant dense<0> : vector<i32>
    %scan, %last = vector.scan <add>, %row, %z0 {inclusive = true, reduction_dim = 0 : i64} : vector<4xi32>, vector<i32>
    %s5 = vector.extract %scan[3] : i32 from vector<4xi32>
    %a0 = arith.addi %s1, %s2 : i32
    %a = arith.addi %a0, %s5 : i32
    %b = arith.addi %s3, %s4 : i32
    %r = arith.addi %a, %b : i32
    %c1000 = arith.constant 1000 : i32
    %y = arith.remsi %r, %c1000 : i32
    %yf = arith.sitofp %y : i32 to f32
    sim.yield %yf : f32
  }
  sim.observe [@A]
}
