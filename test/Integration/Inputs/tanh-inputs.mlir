// tanh of f32 bit patterns: item i, lane k computes tanh of the float whose
// bits are (16 i + k) * @stride + @offset (mod 2^32); NaN patterns become
// infinities of their sign (a NaN payload is not a value to compare). With
// range 2^28 / 16 and stride 1 the items cover every float once; the tests
// take every @stride-th pattern.
sim.simulation @tanh_inputs range(1048576) dt(1.0 : f32) max_steps(1) {
  sim.param @stride = 257 : i32
  sim.param @offset = 0 : i32

  sim.buffer @T : vector<16xf32> init {
  ^bb0(%i: index):
    %z = arith.constant dense<0.0> : vector<16xf32>
    sim.yield %z : vector<16xf32>
  }
  sim.component @Tanh writes(@T) evaluate {
  ^bb0(%i: index, %t: i64, %n: i32, %dt: f32):
    %stride = sim.get_param @stride : i32
    %offset = sim.get_param @offset : i32
    %item = arith.index_cast %i : index to i32
    %c16 = arith.constant 16 : i32
    %first = arith.muli %item, %c16 : i32
    %firsts = vector.broadcast %first : i32 to vector<16xi32>
    %lanes = arith.constant dense<[0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15]> : vector<16xi32>
    %index = arith.addi %firsts, %lanes : vector<16xi32>
    %strides = vector.broadcast %stride : i32 to vector<16xi32>
    %offsets = vector.broadcast %offset : i32 to vector<16xi32>
    %scaled = arith.muli %index, %strides : vector<16xi32>
    %bits = arith.addi %scaled, %offsets : vector<16xi32>
    %exp_mask = arith.constant dense<2139095040> : vector<16xi32>
    %frac_mask = arith.constant dense<8388607> : vector<16xi32>
    %zero = arith.constant dense<0> : vector<16xi32>
    %exp = arith.andi %bits, %exp_mask : vector<16xi32>
    %frac = arith.andi %bits, %frac_mask : vector<16xi32>
    %all_ones = arith.cmpi eq, %exp, %exp_mask : vector<16xi32>
    %some_frac = arith.cmpi ne, %frac, %zero : vector<16xi32>
    %nan = arith.andi %all_ones, %some_frac : vector<16xi1>
    %no_frac = arith.xori %bits, %frac : vector<16xi32>
    %finite_bits = arith.select %nan, %no_frac, %bits : vector<16xi1>, vector<16xi32>
    %x = arith.bitcast %finite_bits : vector<16xi32> to vector<16xf32>
    %y = math.tanh %x : vector<16xf32>
    sim.yield %y : vector<16xf32>
  }
  sim.schedule [@Tanh]
  sim.observe [@T]
}
