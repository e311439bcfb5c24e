// A small scene for the bundle tests, with a bit of everything the scene
// section records: f32, f64 and vector buffers, every interpolation and
// boundary rule, an exact solution, and parameters of four types.
//
// @Move (an oscillator chain, position @X and velocity @V, pushed by @S
// through the back edge) bounds the big step: @steps - i % 2 base steps, at
// least 1. @Smooth reads @X in a window, interpolated under hip (Hermite
// with @V), and sub-steps in the kernel, 1 + i % @steps base steps at a
// time. @Diffuse sub-steps likewise, with a grid-wide barrier (it reads its
// neighbours' @D). @Decay has no num_steps and an exact solution. With
// @steps = 1 every num_steps is 1, so every strategy takes single base steps
// and must equal simple bit for bit.
sim.simulation @mixed range(200) dt(1.0e-2 : f64) max_steps(4) {
  sim.param @steps = 3 : i32
  sim.param @k = 5.0e-1 : f64
  sim.param @gain = 1.25 : f32
  sim.param @seed = 42 : i64
  sim.param @width = 2 : index

  sim.buffer @X : f64 interp(#sim.hermite<@V>) boundary(wrap) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f64
    %s = arith.constant 1.0e-1 : f64
    %a = arith.mulf %f, %s : f64
    %x = math.sin %a : f64
    sim.yield %x : f64
  }
  sim.buffer @V : f64 interp(none) boundary(wrap) init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f64
    sim.yield %zero : f64
  }
  sim.buffer @S : vector<2xf32> interp(#sim.cubic) boundary(zero) init {
  ^bb0(%i: index):
    %zero = arith.constant dense<0.0> : vector<2xf32>
    sim.yield %zero : vector<2xf32>
  }
  sim.buffer @D : f32 init {
  ^bb0(%i: index):
    %zero = arith.constant 0.0 : f32
    sim.yield %zero : f32
  }
  sim.buffer @E : f64 interp(#sim.linear) init {
  ^bb0(%i: index):
    %one = arith.constant 1.0 : f64
    sim.yield %one : f64
  } exact {
  ^bb0(%i: index, %t: f64):
    %k = sim.get_param @k : f64
    %kt = arith.mulf %k, %t : f64
    %minus = arith.negf %kt : f64
    %e = math.exp %minus : f64
    sim.yield %e : f64
  }

  sim.component @Move writes(@X, @V) num_steps {
  ^bb0(%i: index, %t: i64):
    %steps = sim.get_param @steps : i32
    %i32 = arith.index_cast %i : index to i32
    %c2 = arith.constant 2 : i32
    %r = arith.remsi %i32, %c2 : i32
    %less = arith.subi %steps, %r : i32
    %c1 = arith.constant 1 : i32
    %n = arith.maxsi %less, %c1 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %left = arith.subi %i, %c1 : index
    %right = arith.addi %i, %c1 : index
    %x = sim.read @X[%i] : f64
    %xl = sim.read @X[%left] : f64
    %xr = sim.read @X[%right] : f64
    %v = sim.read @V[%i] : f64
    %k = sim.get_param @k : f64
    %two = arith.constant 2.0 : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %sum = arith.addf %xl, %xr : f64
    %twox = arith.mulf %two, %x : f64
    %lap = arith.subf %sum, %twox : f64
    %pull = arith.mulf %k, %lap : f64
    %a0 = arith.subf %pull, %x : f64
    %s = sim.read @S[%i] : vector<2xf32>
    %s0 = vector.extract %s[0] : f32 from vector<2xf32>
    %s64 = arith.extf %s0 : f32 to f64
    %tenth = arith.constant 1.0e-1 : f64
    %push = arith.mulf %tenth, %s64 : f64
    %a = arith.addf %a0, %push : f64
    %dv = arith.mulf %h, %a : f64
    %v1 = arith.addf %v, %dv : f64
    %dx = arith.mulf %h, %v1 : f64
    %x1 = arith.addf %x, %dx : f64
    sim.yield %x1, %v1 : f64, f64
  }

  sim.component @Smooth writes(@S) num_steps {
  ^bb0(%i: index, %t: i64):
    %steps = sim.get_param @steps : i32
    %i32 = arith.index_cast %i : index to i32
    %r = arith.remsi %i32, %steps : i32
    %c1 = arith.constant 1 : i32
    %n = arith.addi %r, %c1 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c-2 = arith.constant -2 : index
    %c3 = arith.constant 3 : index
    %c1 = arith.constant 1 : index
    %zero = arith.constant 0.0 : f64
    %sum = scf.for %d = %c-2 to %c3 step %c1 iter_args(%acc = %zero) -> (f64) {
      %j = arith.addi %i, %d : index
      %x = sim.read @X[%j] : f64
      %next = arith.addf %acc, %x : f64
      scf.yield %next : f64
    }
    %fifth = arith.constant 2.0e-1 : f64
    %mean = arith.mulf %sum, %fifth : f64
    %mean32 = arith.truncf %mean : f64 to f32
    %gain = sim.get_param @gain : f32
    %scaled = arith.mulf %mean32, %gain : f32
    %tanh = math.tanh %scaled : f32
    %b = vector.broadcast %tanh : f32 to vector<2xf32>
    %signs = arith.constant dense<[1.0, -1.0]> : vector<2xf32>
    %target = arith.mulf %b, %signs : vector<2xf32>
    %s = sim.read @S[%i] : vector<2xf32>
    %nf = arith.sitofp %n : i32 to f64
    %h64 = arith.mulf %nf, %dt : f64
    %h = arith.truncf %h64 : f64 to f32
    %hv = vector.broadcast %h : f32 to vector<2xf32>
    %delta = arith.subf %target, %s : vector<2xf32>
    %s1 = vector.fma %hv, %delta, %s : vector<2xf32>
    sim.yield %s1 : vector<2xf32>
  }

  sim.component @Diffuse writes(@D) num_steps {
  ^bb0(%i: index, %t: i64):
    %steps = sim.get_param @steps : i32
    %i32 = arith.index_cast %i : index to i32
    %r = arith.remsi %i32, %steps : i32
    %c1 = arith.constant 1 : i32
    %n = arith.addi %r, %c1 : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %left = arith.subi %i, %c1 : index
    %right = arith.addi %i, %c1 : index
    %d = sim.read @D[%i] : f32
    %dl = sim.read @D[%left] : f32
    %dr = sim.read @D[%right] : f32
    %x = sim.read @X[%i] : f64
    %x32 = arith.truncf %x : f64 to f32
    %sum = arith.addf %dl, %dr : f32
    %two = arith.constant 2.0 : f32
    %twod = arith.mulf %two, %d : f32
    %lap = arith.subf %sum, %twod : f32
    %pull = arith.subf %x32, %d : f32
    %rate = arith.addf %lap, %pull : f32
    %nf = arith.sitofp %n : i32 to f64
    %h64 = arith.mulf %nf, %dt : f64
    %h = arith.truncf %h64 : f64 to f32
    %dd = arith.mulf %h, %rate : f32
    %d1 = arith.addf %d, %dd : f32
    sim.yield %d1 : f32
  }

  sim.component @Decay writes(@E) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %e = sim.read @E[%i] : f64
    %k = sim.get_param @k : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %kh = arith.mulf %k, %h : f64
    %minus = arith.negf %kh : f64
    %factor = math.exp %minus : f64
    %e1 = arith.mulf %e, %factor : f64
    sim.yield %e1 : f64
  }

  sim.schedule [@Move, @Smooth, @Diffuse, @Decay]
  sim.observe [@X, @S, @D, @E]
}
