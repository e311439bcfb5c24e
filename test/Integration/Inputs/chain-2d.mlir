// A chain of 2000 beads in the plane, written the way a user would, for
// user-scenes.test: positions and velocities are vector<2xf32> (@P cubic,
// @V linear, ends clamped), each bead pulled by springs to its two
// neighbours (a window i-1..i+1 of the component's own buffer, so lts
// gives its blocks local time steps), with springs 64x stiffer at beads
// 600..799 and a step count that also drops where a bead moves fast (it
// depends on the state). A second component measures the stretch of every
// spring from @P at its own sub-steps (it reads @P in a window between T
// and T + m), and a total sums the kinetic energy in f64.
sim.simulation @chain range(2000) dt(1.0e-3 : f32) max_steps(16) {
  sim.param @k = 4.0e2 : f32
  sim.param @stiff = 6.4e1 : f32

  sim.buffer @P : vector<2xf32> interp(#sim.cubic) boundary(clamp) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %f = arith.sitofp %i64 : i64 to f32
    %h = arith.constant 1.0e-2 : f32
    %x = arith.mulf %f, %h : f32
    %w = arith.constant 3.0e-1 : f32
    %a = arith.mulf %f, %w : f32
    %s = math.sin %a : f32
    %amp = arith.constant 2.0e-3 : f32
    %y = arith.mulf %s, %amp : f32
    %p = vector.from_elements %x, %y : vector<2xf32>
    sim.yield %p : vector<2xf32>
  }
  sim.buffer @V : vector<2xf32> interp(#sim.linear) boundary(clamp) init {
  ^bb0(%i: index):
    %z = arith.constant dense<0.0> : vector<2xf32>
    sim.yield %z : vector<2xf32>
  }
  sim.buffer @S : f32 interp(#sim.linear) init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f32
    sim.yield %z : f32
  }

  sim.component @Move writes(@P, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %lo = arith.constant 600 : index
    %hi = arith.constant 800 : index
    %a = arith.cmpi uge, %i, %lo : index
    %b = arith.cmpi ult, %i, %hi : index
    %stiff = arith.andi %a, %b : i1
    %v = sim.read @V[%i] : vector<2xf32>
    %vy = vector.extract %v[1] : f32 from vector<2xf32>
    %avy = math.absf %vy : f32
    %fastv = arith.constant 5.0e-3 : f32
    %fast = arith.cmpf ogt, %avy, %fastv : f32
    %one = arith.constant 1 : i32
    %four = arith.constant 4 : i32
    %sixteen = arith.constant 16 : i32
    %soft = arith.select %fast, %four, %sixteen : i32
    %n = arith.select %stiff, %one, %soft : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %p = sim.read @P[%i] : vector<2xf32>
    %pl = sim.read @P[%il] : vector<2xf32>
    %pr = sim.read @P[%ir] : vector<2xf32>
    %v = sim.read @V[%i] : vector<2xf32>
    %lo = arith.constant 600 : index
    %hi = arith.constant 800 : index
    %a = arith.cmpi uge, %i, %lo : index
    %b = arith.cmpi ult, %i, %hi : index
    %isstiff = arith.andi %a, %b : i1
    %k = sim.get_param @k : f32
    %ks = sim.get_param @stiff : f32
    %kk = arith.mulf %k, %ks : f32
    %kv = arith.select %isstiff, %kk, %k : f32
    %two = arith.constant dense<2.0> : vector<2xf32>
    %p2 = arith.mulf %p, %two : vector<2xf32>
    %sum = arith.addf %pl, %pr : vector<2xf32>
    %lap = arith.subf %sum, %p2 : vector<2xf32>
    %kb = vector.broadcast %kv : f32 to vector<2xf32>
    %acc = arith.mulf %lap, %kb : vector<2xf32>
    %nf = arith.sitofp %n : i32 to f32
    %h = arith.mulf %nf, %dt : f32
    %hb = vector.broadcast %h : f32 to vector<2xf32>
    %dv = arith.mulf %acc, %hb : vector<2xf32>
    %v1 = arith.addf %v, %dv : vector<2xf32>
    %dp = arith.mulf %v1, %hb : vector<2xf32>
    %p1 = arith.addf %p, %dp : vector<2xf32>
    sim.yield %p1, %v1 : vector<2xf32>, vector<2xf32>
  }

  sim.component @Stretch writes(@S) num_steps {
  ^bb0(%i: index, %t: i64):
    %two = arith.constant 2 : i32
    sim.yield %two : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %c1 = arith.constant 1 : index
    %ir = arith.addi %i, %c1 : index
    %p = sim.read @P[%i] : vector<2xf32>
    %pr = sim.read @P[%ir] : vector<2xf32>
    %d = arith.subf %pr, %p : vector<2xf32>
    %dd = arith.mulf %d, %d : vector<2xf32>
    %z = arith.constant 0.0 : f32
    %l2 = vector.reduction <add>, %dd, %z : vector<2xf32> into f32
    %l = math.sqrt %l2 : f32
    %rest = arith.constant 1.0e-2 : f32
    %s = arith.subf %l, %rest : f32
    sim.yield %s : f32
  }

  sim.total @Kinetic : f64 {
  ^bb0(%i: index):
    %v = sim.read @V[%i] : vector<2xf32>
    %vv = arith.mulf %v, %v : vector<2xf32>
    %z = arith.constant 0.0 : f32
    %s = vector.reduction <add>, %vv, %z : vector<2xf32> into f32
    %half = arith.constant 0.5 : f32
    %e = arith.mulf %s, %half : f32
    %d = arith.extf %e : f32 to f64
    sim.yield %d : f64
  }
  sim.observe [@P, @S]
}
