//===- SimDialect.cpp - the sim dialect -----------------------------------===//
//
// Registers the sim operations and attributes.
//
//===----------------------------------------------------------------------===//

#include "sim/Dialect/Sim/IR/SimDialect.h"
#include "sim/Dialect/Sim/IR/SimOps.h"

using namespace mlir;
using namespace mlir::sim;

#include "sim/Dialect/Sim/IR/SimDialect.cpp.inc"

void SimDialect::initialize() {
  addOperations<
#define GET_OP_LIST
#include "sim/Dialect/Sim/IR/SimOps.cpp.inc"
      >();
  registerAttributes();
}
