// RUN: sim-opt %s --split-input-file --pass-pipeline='builtin.module(gpu.module(sim-gpu-lower-subgroup-reduce))' | FileCheck %s

// A chip before sm_80 has no redux.sync: the warp's minimum of num_steps
// becomes a butterfly of five xor shuffles over its 32 lanes.
// CHECK-LABEL: gpu.func @group_min
// CHECK-NOT: gpu.subgroup_reduce
// CHECK-DAG: %[[C1:.+]] = arith.constant 1 : i32
// CHECK-DAG: %[[C16:.+]] = arith.constant 16 : i32
// CHECK-DAG: %[[C32:.+]] = arith.constant 32 : i32
// CHECK: %[[S1:.+]], %{{.+}} = gpu.shuffle xor %[[X:.+]], %[[C1]], %[[C32]] : i32
// CHECK: arith.minsi %[[X]], %[[S1]] : i32
// CHECK-COUNT-3: gpu.shuffle xor
// CHECK: gpu.shuffle xor %{{.+}}, %[[C16]], %[[C32]] : i32
// CHECK: %[[M:.+]] = arith.minsi
// CHECK: gpu.return %[[M]] : i32
gpu.module @kernels {
  gpu.func @group_min(%x: i32) -> i32 {
    %m = gpu.subgroup_reduce minsi %x uniform : (i32) -> i32
    gpu.return %m : i32
  }
}

// -----

// The evaluation counts: a sum, the same in any order for integers.
// CHECK-LABEL: gpu.func @evaluations
// CHECK-NOT: gpu.subgroup_reduce
// CHECK-COUNT-5: arith.addi
// CHECK: gpu.return
gpu.module @kernels {
  gpu.func @evaluations(%x: i32) -> i32 {
    %s = gpu.subgroup_reduce add %x uniform : (i32) -> i32
    gpu.return %s : i32
  }
}
