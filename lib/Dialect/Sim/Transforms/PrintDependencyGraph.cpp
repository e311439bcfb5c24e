//===- PrintDependencyGraph.cpp - show who reads what ---------------------===//
//
// Prints the dependency analysis of every simulation as a readable listing or
// as Graphviz DOT. The IR is left unchanged. When the schedule can be
// computed, reads are shown with their roles; when it cannot, the graph is
// still printed (it is what a user needs to see to fix the schedule) and
// `--sim-schedule` gives the reason.
//
//===----------------------------------------------------------------------===//

#include "sim/Analysis/DependencyAnalysis.h"
#include "sim/Analysis/Scheduling.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"

#include "llvm/Support/raw_ostream.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMPRINTDEPENDENCYGRAPH
#include "sim/Dialect/Sim/Transforms/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

/// Writes one simulation's graph.
class GraphPrinter {
public:
  GraphPrinter(const DependencyAnalysis &analysis, llvm::raw_ostream &os)
      : analysis(analysis), os(os),
        schedule(computeSchedule(analysis,
                                 getUserOrder(analysis.getSimulation()),
                                 /*emitDiagnostics=*/false)) {}

  void printText();
  void printDot();

private:
  /// The role of a read edge, or std::nullopt without a schedule.
  std::optional<ReadRole> getRole(ComponentOp reader, BufferOp buffer) const {
    if (failed(schedule))
      return std::nullopt;
    return schedule->getRole(reader, analysis.getWriter(buffer));
  }

  static std::string symbol(StringRef name) { return ("@" + name).str(); }
  static std::string escape(StringRef text);

  void printAccesses(ArrayRef<BufferAccess> accesses, BodyKind body,
                     ComponentOp reader);
  void printBounds(ArrayRef<ComponentOp> bounds);

  const DependencyAnalysis &analysis;
  llvm::raw_ostream &os;
  FailureOr<Schedule> schedule;
};

void GraphPrinter::printBounds(ArrayRef<ComponentOp> bounds) {
  if (bounds.empty()) {
    os << "none (max_steps)";
    return;
  }
  llvm::interleaveComma(bounds, os, [&](ComponentOp component) {
    os << symbol(component.getSymName());
  });
}

void GraphPrinter::printAccesses(ArrayRef<BufferAccess> accesses, BodyKind body,
                                 ComponentOp reader) {
  SmallVector<const BufferAccess *> inBody;
  for (const BufferAccess &access : accesses)
    if (access.body == body)
      inBody.push_back(&access);
  os << "    " << stringifyBodyKind(body) << " reads: ";
  if (inBody.empty()) {
    os << "nothing\n";
    return;
  }
  llvm::interleaveComma(inBody, os, [&](const BufferAccess *access) {
    os << symbol(access->buffer.getSymName()) << "[" << access->pattern.str()
       << "]";
    if (!reader)
      return;
    if (std::optional<ReadRole> role = getRole(reader, access->buffer))
      os << " " << stringifyReadRole(*role);
  });
  os << "\n";
}

void GraphPrinter::printText() {
  SimulationOp simulation = analysis.getSimulation();
  os << "dependency graph of " << symbol(simulation.getSymName()) << ": "
     << analysis.getComponents().size() << " components, "
     << analysis.getBuffers().size() << " buffers\n";
  if (succeeded(schedule)) {
    os << "  schedule: ";
    llvm::interleaveComma(schedule->getOrder(), os,
                          [&](ComponentOp c) { os << symbol(c.getSymName()); });
    os << "\n  hip step bounded by: ";
    printBounds(schedule->getHipStepBounds(analysis));
    os << "\n  traditional step bounded by: ";
    printBounds(schedule->getTraditionalStepBounds());
    os << "\n";
  } else {
    os << "  schedule: undetermined (--sim-schedule reports why)\n";
  }

  for (ComponentOp component : analysis.getComponents()) {
    os << "  component " << symbol(component.getSymName()) << " writes ";
    llvm::interleaveComma(analysis.getWrittenBuffers(component), os,
                          [&](BufferOp b) { os << symbol(b.getSymName()); });
    os << "\n";
    if (component.hasNumSteps())
      printAccesses(analysis.getAccesses(component), BodyKind::NumSteps,
                    component);
    printAccesses(analysis.getAccesses(component), BodyKind::Evaluate,
                  component);
    const BufferAccess *hazard = analysis.findSubStepHazard(component);
    os << "    sub-stepping: " << (hazard ? "grid_sync" : "in_kernel") << "\n";
  }

  for (BufferOp buffer : analysis.getBuffers()) {
    os << "  buffer " << symbol(buffer.getSymName()) << " : "
       << buffer.getElementType() << " interp " << buffer.getInterpolation()
       << ", written by " << symbol(analysis.getWriter(buffer).getSymName())
       << "\n";
    printAccesses(analysis.getAccesses(buffer), BodyKind::Init, nullptr);
    if (!buffer.getExact().empty())
      printAccesses(analysis.getAccesses(buffer), BodyKind::Exact, nullptr);
  }

  os << "  edges:\n";
  for (ComponentOp reader : analysis.getComponents()) {
    for (ComponentOp producer : analysis.getProducers(reader)) {
      for (BufferOp buffer : analysis.getBuffersReadFrom(reader, producer)) {
        os << "    " << symbol(producer.getSymName()) << " -> "
           << symbol(reader.getSymName()) << " via "
           << symbol(buffer.getSymName()) << "["
           << analysis.getReadPattern(reader, buffer)->str() << "]";
        if (std::optional<ReadRole> role = getRole(reader, buffer))
          os << " " << stringifyReadRole(*role);
        os << "\n";
      }
    }
  }
}

std::string GraphPrinter::escape(StringRef text) {
  std::string result;
  for (char c : text) {
    if (c == '"' || c == '\\')
      result += '\\';
    result += c;
  }
  return result;
}

void GraphPrinter::printDot() {
  SimulationOp simulation = analysis.getSimulation();
  std::string name = escape(simulation.getSymName());
  auto componentId = [](ComponentOp c) {
    return "\"c_" + escape(c.getSymName()) + "\"";
  };
  auto bufferId = [](BufferOp b) {
    return "\"b_" + escape(b.getSymName()) + "\"";
  };
  SmallVector<ComponentOp> hipBounds;
  if (succeeded(schedule))
    hipBounds = schedule->getHipStepBounds(analysis);

  os << "digraph \"" << name << "\" {\n";
  os << "  label=\"@" << name << "\";\n  labelloc=t;\n  rankdir=LR;\n";
  os << "  node [fontname=\"Helvetica\"];\n  edge [fontname=\"Helvetica\"];\n";
  for (ComponentOp component : analysis.getComponents()) {
    std::string label = "@" + escape(component.getSymName());
    if (succeeded(schedule))
      label += "\\n#" + std::to_string(schedule->getPosition(component));
    if (llvm::is_contained(hipBounds, component))
      label += "\\nbounds the hip step";
    if (analysis.findSubStepHazard(component))
      label += "\\ngrid_sync";
    os << "  " << componentId(component) << " [shape=box, label=\"" << label
       << "\"];\n";
  }
  for (BufferOp buffer : analysis.getBuffers()) {
    std::string type;
    llvm::raw_string_ostream(type) << buffer.getElementType();
    os << "  " << bufferId(buffer) << " [shape=ellipse, label=\"@"
       << escape(buffer.getSymName()) << "\\n"
       << escape(type) << "\"];\n";
  }
  for (ComponentOp component : analysis.getComponents())
    for (BufferOp buffer : analysis.getWrittenBuffers(component))
      os << "  " << componentId(component) << " -> " << bufferId(buffer)
         << " [label=\"writes\"];\n";
  for (ComponentOp reader : analysis.getComponents()) {
    llvm::SmallPtrSet<Operation *, 8> seen;
    for (const BufferAccess &access : analysis.getAccesses(reader)) {
      if (!seen.insert(access.buffer).second)
        continue;
      std::string label = analysis.getReadPattern(reader, access.buffer)->str();
      std::optional<ReadRole> role = getRole(reader, access.buffer);
      std::string style;
      if (role) {
        label += std::string("\\n") + stringifyReadRole(*role).str();
        if (*role == ReadRole::back_edge)
          style = ", style=dashed, color=purple, fontcolor=purple";
      }
      os << "  " << bufferId(access.buffer) << " -> " << componentId(reader)
         << " [label=\"" << label << "\"" << style << "];\n";
    }
  }
  os << "}\n";
}

struct PrintDependencyGraphPass
    : public sim::impl::SimPrintDependencyGraphBase<PrintDependencyGraphPass> {
  using SimPrintDependencyGraphBase::SimPrintDependencyGraphBase;

  void runOnOperation() override {
    // Walk in program order so the output is deterministic.
    bool failedAny = false;
    getOperation()->walk([&](SimulationOp simulation) {
      if (failed(simulation.checkConstantsInlined(getArgument()))) {
        failedAny = true;
        return;
      }
      DependencyAnalysis analysis(simulation);
      GraphPrinter printer(analysis, llvm::outs());
      if (format == GraphFormat::dot)
        printer.printDot();
      else
        printer.printText();
    });
    llvm::outs().flush();
    if (failedAny)
      return signalPassFailure();
    markAllAnalysesPreserved();
  }
};

} // namespace
