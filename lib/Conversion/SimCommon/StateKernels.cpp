//===- StateKernels.cpp - kernels of states, exact solutions and totals ---===//
//
// init_B (a buffer's initial state), exact_B (its exact solution at a
// time the runtime gives) and total_T (a total's value at every item at the
// current T).
//
//===----------------------------------------------------------------------===//

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "sim/Conversion/SimCommon/KernelNames.h"
#include "sim/Conversion/SimCommon/SimulationLowering.h"

using namespace mlir;
using namespace mlir::sim;

/// The initial state of one buffer, into half 0.
LogicalResult SimulationLowering::emitInit(BufferOp buffer,
                                           OpBuilder &launches) {
  Kernel kernel =
      beginKernel(getKernelName(kernels, "init", buffer.getSymName()));
  Value memory = kernel.values.buffers.lookup(buffer.getSymNameAttr());
  forEachItem(kernel, [&](const Lane &lane) {
    b.ifThen(lane.active, [&] {
      KernelValues values = kernel.values;
      values.item = lane.item;
      Value value = inline_(buffer.getInit(), {lane.item}, values).front();
      b.store(value, memory,
              element(kernel, lane.item, buffer.getSymNameAttr()));
    });
  });
  if (distributed && travels(buffer))
    pendingExchange.push_back(FlatSymbolRefAttr::get(buffer.getSymNameAttr()));
  return endKernel(kernel, simplan::LaunchShape::items, launches);
}

/// The exact solution of one buffer at the launch's time argument.
LogicalResult SimulationLowering::emitExact(BufferOp buffer,
                                            OpBuilder &launches) {
  Kernel kernel =
      beginKernel(getKernelName(kernels, "exact", buffer.getSymName()), buffer);
  Value out = kernel.values.snapshots.lookup(buffer.getSymNameAttr());
  kernel.values.snapshots.erase(buffer.getSymNameAttr());
  forEachItem(kernel, [&](const Lane &lane) {
    b.ifThen(lane.active, [&] {
      KernelValues values = kernel.values;
      values.item = lane.item;
      Value value =
          inline_(buffer.getExact(), {lane.item, kernel.time}, values).front();
      b.store(value, out, element(kernel, lane.item, buffer.getSymNameAttr()));
    });
  });
  return endKernel(kernel, simplan::LaunchShape::items, launches);
}

/// The value of one total at every item, at the current T (after a run's
/// finish, or after init): reads load the source half, the one the clock's
/// parity selects. The per-item values go out as f64; the runtime sums them.
LogicalResult SimulationLowering::emitTotal(TotalOp total,
                                            OpBuilder &launches) {
  Kernel kernel =
      beginKernel(getKernelName(kernels, "total", total.getSymName()),
                  /*exactOf=*/nullptr, total);
  Value parity = b.load(kernel.clock, b.index(kSlotParity));
  kernel.values.sourceBase = b.mul(b.toIndex(parity), kernel.values.extent);
  kernel.values.sourceParity = parity;
  forEachItem(kernel, [&](const Lane &lane) {
    b.ifThen(lane.active, [&] {
      KernelValues values = kernel.values;
      values.item = lane.item;
      Value value = inline_(total.getBody(), {lane.item}, values).front();
      if (!value.getType().isF64())
        value = arith::ExtFOp::create(b, b.loc, b.getF64Type(), value);
      b.store(value, kernel.totalOut, element(kernel, lane.item));
    });
  });
  return endKernel(kernel, simplan::LaunchShape::items, launches);
}
