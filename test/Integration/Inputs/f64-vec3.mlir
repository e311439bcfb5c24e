// f64 elements and vector<3xf32> elements (12 bytes of data, a 16-byte
// stride on the device): a vec3 buffer read in a window (i-2..i+2,
// interpolated, cached under hip-cache) and an f64 buffer read through the
// back edge.
//
// @Spin rotates @P (vector<3xf32>) about z by n dt (1 + E) radians, where
// E (f64) comes through the back edge; 3 + i % 3 base steps (more than max_steps): it bounds
// the hip step at max_steps (3). @Blur writes @Q, the mean of P[i-2..i+2] (boundary wrap), in one
// evaluation per big step. @Energy relaxes @E (f64) towards |Q|^2 (in f64),
// 1 + i % 2 base steps at a time.
sim.simulation @f64_vec3 range(40) dt(5.0e-2 : f64) max_steps(3) {
  sim.param @force = 0 : i32

  sim.buffer @P : vector<3xf32> boundary(wrap) init {
  ^bb0(%i: index):
    %i32 = arith.index_cast %i : index to i32
    %f = arith.sitofp %i32 : i32 to f32
    %s = arith.constant 2.5e-1 : f32
    %a = arith.mulf %f, %s : f32
    %c = math.cos %a : f32
    %n = math.sin %a : f32
    %z = arith.constant 5.0e-1 : f32
    %v0 = vector.from_elements %c, %n, %z : vector<3xf32>
    sim.yield %v0 : vector<3xf32>
  }
  sim.buffer @Q : vector<3xf32> init {
  ^bb0(%i: index):
    %z = arith.constant dense<0.0> : vector<3xf32>
    sim.yield %z : vector<3xf32>
  }
  sim.buffer @E : f64 init {
  ^bb0(%i: index):
    %z = arith.constant 0.0 : f64
    sim.yield %z : f64
  }

  sim.component @Spin writes(@P) num_steps {
  ^bb0(%i: index, %t: i64):
    %force = sim.get_param @force : i32
    %i32 = arith.index_cast %i : index to i32
    %c3 = arith.constant 3 : i32
    %c1 = arith.constant 1 : i32
    %c0 = arith.constant 0 : i32
    %r = arith.remsi %i32, %c3 : i32
    %n = arith.addi %r, %c3 : i32
    %f = arith.cmpi ne, %force, %c0 : i32
    %m = arith.select %f, %c1, %n : i32
    sim.yield %m : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %p = sim.read @P[%i] : vector<3xf32>
    %e = sim.read @E[%i] : f64
    %one = arith.constant 1.0 : f64
    %rate = arith.addf %one, %e : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %ang64 = arith.mulf %h, %rate : f64
    %ang = arith.truncf %ang64 : f64 to f32
    %c = math.cos %ang : f32
    %s = math.sin %ang : f32
    %x = vector.extract %p[0] : f32 from vector<3xf32>
    %y = vector.extract %p[1] : f32 from vector<3xf32>
    %z = vector.extract %p[2] : f32 from vector<3xf32>
    %xc = arith.mulf %x, %c : f32
    %ys = arith.mulf %y, %s : f32
    %x1 = arith.subf %xc, %ys : f32
    %xs = arith.mulf %x, %s : f32
    %yc = arith.mulf %y, %c : f32
    %y1 = arith.addf %xs, %yc : f32
    %p1 = vector.from_elements %x1, %y1, %z : vector<3xf32>
    sim.yield %p1 : vector<3xf32>
  }

  sim.component @Blur writes(@Q) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %lo = arith.constant -2 : index
    %hi = arith.constant 3 : index
    %step = arith.constant 1 : index
    %zero = arith.constant dense<0.0> : vector<3xf32>
    %sum = scf.for %k = %lo to %hi step %step iter_args(%acc = %zero) -> (vector<3xf32>) {
      %j = arith.addi %i, %k : index
      %p = sim.read @P[%j] : vector<3xf32>
      %next = arith.addf %acc, %p : vector<3xf32>
      scf.yield %next : vector<3xf32>
    }
    %fifth = arith.constant dense<2.0e-1> : vector<3xf32>
    %q = arith.mulf %sum, %fifth : vector<3xf32>
    sim.yield %q : vector<3xf32>
  }

  sim.component @Energy writes(@E) num_steps {
  ^bb0(%i: index, %t: i64):
    %force = sim.get_param @force : i32
    %i32 = arith.index_cast %i : index to i32
    %c2 = arith.constant 2 : i32
    %c1 = arith.constant 1 : i32
    %c0 = arith.constant 0 : i32
    %r = arith.remsi %i32, %c2 : i32
    %n = arith.addi %r, %c1 : i32
    %f = arith.cmpi ne, %force, %c0 : i32
    %m = arith.select %f, %c1, %n : i32
    sim.yield %m : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %q = sim.read @Q[%i] : vector<3xf32>
    %q64 = arith.extf %q : vector<3xf32> to vector<3xf64>
    %sq = arith.mulf %q64, %q64 : vector<3xf64>
    %zero = arith.constant 0.0 : f64
    %r2 = vector.reduction <add>, %sq, %zero : vector<3xf64> into f64
    %e = sim.read @E[%i] : f64
    %d = arith.subf %r2, %e : f64
    %nf = arith.sitofp %n : i32 to f64
    %h = arith.mulf %nf, %dt : f64
    %e1 = math.fma %h, %d, %e : f64
    sim.yield %e1 : f64
  }

  sim.schedule [@Spin, @Blur, @Energy]
  sim.observe [@P, @Q, @E]
}
