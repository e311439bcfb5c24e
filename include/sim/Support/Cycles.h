//===- Cycles.h - find a cycle in a small directed graph --------*- C++ -*-===//
//
// The verifier (initial states that read each other) and the scheduler
// (components that depend on each other) both must name a cycle to the user.
// This is the one depth-first search they share.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_SUPPORT_CYCLES_H
#define SIM_SUPPORT_CYCLES_H

#include "llvm/ADT/ArrayRef.h"
#include "llvm/ADT/DenseMap.h"
#include "llvm/ADT/STLExtras.h"
#include "llvm/ADT/SmallVector.h"

#include <algorithm>
#include <functional>

namespace mlir::sim {

/// Returns a cycle of the directed graph over `nodes` whose edges go from a
/// node to each element of `successors(node)`: every node of the result has
/// an edge to the next one, the last to the first. The cycle starts at its
/// node that comes first in `nodes`, so messages do not depend on the search
/// order. Returns an empty list when the graph has no cycle.
template <typename NodeT, typename SuccessorsFn>
llvm::SmallVector<NodeT> findCycle(llvm::ArrayRef<NodeT> nodes,
                                   SuccessorsFn &&successors) {
  enum class Mark { Unvisited, OnStack, Done };
  llvm::DenseMap<NodeT, Mark> marks;
  llvm::SmallVector<NodeT> stack, cycle;
  std::function<bool(NodeT)> visit = [&](NodeT node) {
    marks[node] = Mark::OnStack;
    stack.push_back(node);
    for (NodeT next : successors(node)) {
      Mark mark = marks.lookup(next);
      if (mark == Mark::OnStack) {
        cycle.assign(llvm::find(stack, next), stack.end());
        return true;
      }
      if (mark == Mark::Unvisited && visit(next))
        return true;
    }
    stack.pop_back();
    marks[node] = Mark::Done;
    return false;
  };
  for (NodeT node : nodes) {
    if (marks.lookup(node) != Mark::Unvisited || !visit(node))
      continue;
    auto first = llvm::min_element(cycle, [&](NodeT a, NodeT b) {
      return llvm::find(nodes, a) < llvm::find(nodes, b);
    });
    std::rotate(cycle.begin(), first, cycle.end());
    return cycle;
  }
  return {};
}

} // namespace mlir::sim

#endif // SIM_SUPPORT_CYCLES_H
