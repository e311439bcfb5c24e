// High-level vector ops in a component body, for vector-ops.test: a dot
// product (vector.contract), an outer product, multi-reductions (over one
// dimension and over both), a transpose, vector.step and an fpowi of
// vectors, on a vector<4xf32> state that a stencil reads at its neighbours.
sim.simulation @vector_ops range(100) dt(1.0e-3 : f32) max_steps(4) {
  sim.buffer @U : vector<4xf32> boundary(wrap) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 1.0e-1 : f32
    %a = arith.mulf %f, %s : f32
    %x = math.sin %a : f32
    %v = vector.broadcast %x : f32 to vector<4xf32>
    %k = vector.step : vector<4xindex>
    %ki = arith.index_cast %k : vector<4xindex> to vector<4xi32>
    %kf = arith.sitofp %ki : vector<4xi32> to vector<4xf32>
    %r = arith.addf %v, %kf : vector<4xf32>
    sim.yield %r : vector<4xf32>
  }
  sim.component @Mix writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %i32 = arith.index_cast %i : index to i32
    %c10 = arith.constant 10 : i32
    %lt = arith.cmpi slt, %i32, %c10 : i32
    %one = arith.constant 1 : i32
    %four = arith.constant 4 : i32
    %n = arith.select %lt, %one, %four : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %ip = arith.addi %i, %c1 : index
    %u = sim.read @U[%i] : vector<4xf32>
    %w = sim.read @U[%ip] : vector<4xf32>
    %z = arith.constant 0.0 : f32
    %dot = vector.contract {indexing_maps = [affine_map<(d0) -> (d0)>, affine_map<(d0) -> (d0)>, affine_map<(d0) -> ()>], iterator_types = ["reduction"], kind = #vector.kind<add>} %u, %w, %z : vector<4xf32>, vector<4xf32> into f32
    %outer = vector.outerproduct %u, %w : vector<4xf32>, vector<4xf32>
    %tr = vector.transpose %outer, [1, 0] : vector<4x4xf32> to vector<4x4xf32>
    %col = vector.multi_reduction <add>, %tr, %u [0] : vector<4x4xf32> to vector<4xf32>
    %k = vector.step : vector<4xindex>
    %ki = arith.index_cast %k : vector<4xindex> to vector<4xi32>
    %kf = arith.sitofp %ki : vector<4xi32> to vector<4xf32>
    %all = vector.multi_reduction <add>, %outer, %z [0, 1] : vector<4x4xf32> to f32
    %two = arith.constant dense<2> : vector<4xi32>
    %sq = math.fpowi %u, %two : vector<4xf32>, vector<4xi32>
    %tiny = arith.constant 1.0e-3 : f32
    %allt = arith.mulf %all, %tiny : f32
    %dot2 = arith.addf %dot, %allt : f32
    %dv0 = vector.broadcast %dot2 : f32 to vector<4xf32>
    %sqt = vector.broadcast %tiny : f32 to vector<4xf32>
    %sqs = arith.mulf %sq, %sqt : vector<4xf32>
    %dv = arith.subf %dv0, %sqs : vector<4xf32>
    %s1 = arith.addf %col, %dv : vector<4xf32>
    %s2 = arith.subf %s1, %kf : vector<4xf32>
    %small = arith.constant dense<1.0e-2> : vector<4xf32>
    %rhs = arith.mulf %s2, %small : vector<4xf32>
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %hv = vector.broadcast %h : f32 to vector<4xf32>
    %damp = arith.constant dense<-1.0> : vector<4xf32>
    %du = arith.mulf %u, %damp : vector<4xf32>
    %f = arith.addf %rhs, %du : vector<4xf32>
    %r = vector.fma %hv, %f, %u : vector<4xf32>
    sim.yield %r : vector<4xf32>
  }
  sim.observe [@U]
}
