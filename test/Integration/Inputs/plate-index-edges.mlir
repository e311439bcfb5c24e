// A 64 x 64 heat plate stored row by row, with a stiff square in the
// middle (100x), that masks the ends of its rows on the index instead of on
// the value: the left neighbour of a cell in the first column is the cell
// itself (`arith.select %at_left, %i, %i - 1`), and likewise on the right.
// Either of two windows is a window (docs/Model.md), so the reads are
// i-64..i+64 and under lts the blocks take local time steps.
sim.simulation @plate range(4096) dt(1.0e-6 : f64) max_steps(64) {
  sim.param @nx = 64 : i64
  sim.param @k = 1.0e-2 : f64
  sim.buffer @U : f64 interp(#sim.linear) init {
  ^bb0(%i: index):
    %i64 = arith.index_cast %i : index to i64
    %nx = sim.get_param @nx : i64
    %x = arith.remsi %i64, %nx : i64
    %y = arith.divsi %i64, %nx : i64
    %s = arith.addi %x, %y : i64
    %f = arith.sitofp %s : i64 to f64
    %c = arith.constant 0.05 : f64
    %a = arith.mulf %f, %c : f64
    %u = math.sin %a : f64
    sim.yield %u : f64
  }
  sim.component @Diffuse writes(@U) num_steps {
  ^bb0(%i: index, %t: i64):
    %i64 = arith.index_cast %i : index to i64
    %nx = sim.get_param @nx : i64
    %x = arith.remsi %i64, %nx : i64
    %y = arith.divsi %i64, %nx : i64
    %lo = arith.constant 20 : i64
    %hi = arith.constant 44 : i64
    %x1 = arith.cmpi sge, %x, %lo : i64
    %x2 = arith.cmpi slt, %x, %hi : i64
    %y1 = arith.cmpi sge, %y, %lo : i64
    %y2 = arith.cmpi slt, %y, %hi : i64
    %a = arith.andi %x1, %x2 : i1
    %b = arith.andi %y1, %y2 : i1
    %in = arith.andi %a, %b : i1
    %one = arith.constant 1 : i32
    %many = arith.constant 64 : i32
    %n = arith.select %in, %one, %many : i32
    sim.yield %n : i32
  } evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f64):
    %c1 = arith.constant 1 : index
    %c64 = arith.constant 64 : index
    %il = arith.subi %i, %c1 : index
    %ir = arith.addi %i, %c1 : index
    %id = arith.subi %i, %c64 : index
    %iu = arith.addi %i, %c64 : index
    %item = arith.index_cast %i : index to i64
    %width = sim.get_param @nx : i64
    %column = arith.remsi %item, %width : i64
    %first = arith.constant 0 : i64
    %last = arith.constant 63 : i64
    %at_left = arith.cmpi eq, %column, %first : i64
    %at_right = arith.cmpi eq, %column, %last : i64
    %jl = arith.select %at_left, %i, %il : index
    %jr = arith.select %at_right, %i, %ir : index
    %ul = sim.read @U[%jl] : f64
    %ur = sim.read @U[%jr] : f64
    %ud = sim.read @U[%id] : f64
    %uu = sim.read @U[%iu] : f64
    %u0 = sim.read @U[%i] : f64
    %i64 = arith.index_cast %i : index to i64
    %nx = sim.get_param @nx : i64
    %x = arith.remsi %i64, %nx : i64
    %s1 = arith.addf %ul, %ur : f64
    %s2 = arith.addf %ud, %uu : f64
    %s = arith.addf %s1, %s2 : f64
    %four = arith.constant 4.0 : f64
    %c = arith.mulf %four, %u0 : f64
    %lap = arith.subf %s, %c : f64
    %y = arith.divsi %i64, %nx : i64
    %lo = arith.constant 20 : i64
    %hi = arith.constant 44 : i64
    %x1 = arith.cmpi sge, %x, %lo : i64
    %x2 = arith.cmpi slt, %x, %hi : i64
    %y1 = arith.cmpi sge, %y, %lo : i64
    %y2 = arith.cmpi slt, %y, %hi : i64
    %a = arith.andi %x1, %x2 : i1
    %b = arith.andi %y1, %y2 : i1
    %in = arith.andi %a, %b : i1
    %k = sim.get_param @k : f64
    %hundred = arith.constant 100.0 : f64
    %ks = arith.mulf %k, %hundred : f64
    %kk = arith.select %in, %ks, %k : f64
    %h2 = arith.constant 4096.0 : f64
    %r0 = arith.mulf %kk, %h2 : f64
    %rate = arith.mulf %r0, %lap : f64
    %nf = arith.sitofp %n : i32 to f64
    %step = arith.mulf %nf, %dt : f64
    %u1 = math.fma %step, %rate, %u0 : f64
    sim.yield %u1 : f64
  }
  sim.total @Heat : f64 {
  ^bb0(%i: index):
    %u = sim.read @U[%i] : f64
    sim.yield %u : f64
  }
  sim.observe [@U]
}
