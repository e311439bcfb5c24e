// The checked-in gravity_like.mlir and pbd_like.mlir are exactly what
// python/gen_paper_examples.py generates, and --check notices when they are
// not (here on a copy with one line changed).
//
// RUN: %python %sim_src_root/python/gen_paper_examples.py --check
//
// RUN: rm -rf %t && mkdir -p %t
// RUN: %python %sim_src_root/python/gen_paper_examples.py --output-dir %t \
// RUN:   | FileCheck %s --check-prefix=WROTE
// RUN: %python %sim_src_root/python/gen_paper_examples.py --output-dir %t --check
// RUN: sed -i -e 's/sim.param @L = 8 : i32/sim.param @L = 9 : i32/' %t/pbd_like.mlir
// RUN: not %python %sim_src_root/python/gen_paper_examples.py --output-dir %t \
// RUN:   --check 2>&1 | FileCheck %s --check-prefix=STALE

// WROTE: wrote {{.*}}gravity_like.mlir
// WROTE: wrote {{.*}}pbd_like.mlir

// STALE: -  sim.param @L = 9 : i32
// STALE-NEXT: +  sim.param @L = 8 : i32
// STALE: error: {{.*}}pbd_like.mlir out of date; run python3 python/gen_paper_examples.py
