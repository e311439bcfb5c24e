// A scene whose result is exactly what a fused multiply-add gives and not
// what a multiply and an add give: with x = 1 + 2^-12 and c = -(1 + 2^-11),
// fma(x, x, c) = 2^-24 (x * x = 1 + 2^-11 + 2^-24 is exact before the one
// rounding), but x * x rounds to 1 + 2^-11 on its own, and x * x + c is 0.
// @V uses vector.fma on f32, @W math.fma on f64 (x = 1 + 2^-27,
// c = -(1 + 2^-26): 2^-54 fused, 0 not). The operands are parameters, which
// are kernel arguments, so no compiler can fold the fma away.
// test/Integration/fused-multiply-add.test.
sim.simulation @fused range(40) dt(1.0e-2 : f32) max_steps(2) {
  sim.param @x = 1.000244140625 : f32
  sim.param @c = -1.00048828125 : f32
  sim.param @y = 1.0000000074505806 : f64
  sim.param @d = -1.0000000149011612 : f64

  sim.buffer @V : vector<4xf32> init {
  ^bb0(%i: index):
    %x = sim.get_param @x : f32
    %c = sim.get_param @c : f32
    %xv = vector.broadcast %x : f32 to vector<4xf32>
    %cv = vector.broadcast %c : f32 to vector<4xf32>
    %v = vector.fma %xv, %xv, %cv : vector<4xf32>
    sim.yield %v : vector<4xf32>
  }
  sim.buffer @W : f64 init {
  ^bb0(%i: index):
    %y = sim.get_param @y : f64
    %d = sim.get_param @d : f64
    %w = math.fma %y, %y, %d : f64
    sim.yield %w : f64
  }
  sim.component @Vector writes(@V) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %x = sim.get_param @x : f32
    %c = sim.get_param @c : f32
    %xv = vector.broadcast %x : f32 to vector<4xf32>
    %cv = vector.broadcast %c : f32 to vector<4xf32>
    %v = vector.fma %xv, %xv, %cv : vector<4xf32>
    sim.yield %v : vector<4xf32>
  }
  sim.component @Scalar writes(@W) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %y = sim.get_param @y : f64
    %d = sim.get_param @d : f64
    %w = math.fma %y, %y, %d : f64
    sim.yield %w : f64
  }
  sim.schedule [@Vector, @Scalar]
  sim.observe [@V, @W]
}
