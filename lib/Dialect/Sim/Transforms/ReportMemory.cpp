//===- ReportMemory.cpp - bytes of the memory plan ------------------------===//
//
// Makes "model only what a scene needs" a number: the device memory of the
// plan recorded by --sim-plan-memory (two halves per buffer plus planned
// snapshots) against the naive plan of Algorithm 2 applied to every buffer
// (source, target and a snapshot each), and the shared memory per thread
// group of the planned hip-cache caches.
//
//===----------------------------------------------------------------------===//

#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"

#include "llvm/Support/CheckedArithmetic.h"
#include "llvm/Support/Format.h"
#include "llvm/Support/JSON.h"
#include "llvm/Support/raw_ostream.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMREPORTMEMORY
#include "sim/Dialect/Sim/Transforms/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

struct BufferRow {
  std::string name, type;
  int64_t elementBytes, halvesBytes, snapshotBytes, totalBytes;
};

struct CacheRow {
  std::string component;
  int64_t bytesPerGroup;
};

/// The numbers of one simulation's plan.
struct MemoryReport {
  std::string simulation, strategy;
  int64_t range = 0;
  SmallVector<BufferRow> buffers;
  SmallVector<CacheRow> caches;
  /// Device bytes of the plan and of the naive plan (3 copies of each
  /// buffer); planned <= naive, so the difference cannot overflow.
  int64_t plannedBytes = 0, naiveBytes = 0;

  int64_t planned() const { return plannedBytes; }
  int64_t naive() const { return naiveBytes; }
  int64_t largestCache() const {
    int64_t largest = 0;
    for (const CacheRow &row : caches)
      largest = std::max(largest, row.bytesPerGroup);
    return largest;
  }
};

std::string formatBytes(int64_t bytes) {
  std::string text;
  llvm::raw_string_ostream os(text);
  if (bytes >= (int64_t(1) << 20))
    os << llvm::format("%.2f MiB", double(bytes) / double(1 << 20));
  else if (bytes >= 1024)
    os << llvm::format("%.2f KiB", double(bytes) / 1024.0);
  else
    os << bytes << " B";
  return text;
}

void printText(const MemoryReport &report, int64_t groupSize,
               llvm::raw_ostream &os) {
  os << "memory plan of @" << report.simulation << " (strategy "
     << report.strategy << ", " << report.range << " items)\n";
  os << llvm::format("  %-12s %-16s %10s %14s %14s %14s\n", "buffer", "element",
                     "bytes/item", "halves", "snapshot", "total");
  for (const BufferRow &row : report.buffers)
    os << llvm::format("  %-12s %-16s %10lld %14lld %14lld %14lld\n",
                       ("@" + row.name).c_str(), row.type.c_str(),
                       (long long)row.elementBytes, (long long)row.halvesBytes,
                       (long long)row.snapshotBytes, (long long)row.totalBytes);
  int64_t planned = report.planned(), naive = report.naive();
  os << llvm::format("  %-40s %14lld (%s)\n", "planned device memory",
                     (long long)planned, formatBytes(planned).c_str());
  os << llvm::format("  %-40s %14lld (%s)\n",
                     "naive plan (3 copies of every buffer)", (long long)naive,
                     formatBytes(naive).c_str());
  if (naive > 0)
    os << llvm::format("  %-40s %14lld (%.1f%%)\n", "saved",
                       (long long)(naive - planned),
                       100.0 * double(naive - planned) / double(naive));
  if (report.caches.empty()) {
    os << "  shared-memory caches: none\n";
    return;
  }
  os << "  shared-memory caches (" << groupSize << " threads per group):\n";
  for (const CacheRow &row : report.caches)
    os << llvm::format("    %-12s %10lld bytes per group\n",
                       ("@" + row.component).c_str(),
                       (long long)row.bytesPerGroup);
}

llvm::json::Value toJson(const MemoryReport &report, int64_t groupSize) {
  llvm::json::Array buffers, caches;
  for (const BufferRow &row : report.buffers)
    buffers.push_back(
        llvm::json::Object{{"name", row.name},
                           {"element", row.type},
                           {"bytes_per_item", row.elementBytes},
                           {"halves_bytes", row.halvesBytes},
                           {"snapshot_bytes", row.snapshotBytes}});
  for (const CacheRow &row : report.caches)
    caches.push_back(llvm::json::Object{
        {"component", row.component}, {"bytes_per_group", row.bytesPerGroup}});
  return llvm::json::Object{
      {"simulation", report.simulation},
      {"strategy", report.strategy},
      {"range", report.range},
      {"group_size", groupSize},
      {"buffers", std::move(buffers)},
      {"caches", std::move(caches)},
      {"planned_bytes", report.planned()},
      {"naive_bytes", report.naive()},
      {"largest_cache_bytes_per_group", report.largestCache()}};
}

/// Byte counts of one simulation, in checked arithmetic: a scene whose
/// memory does not fit in int64_t (a range near 2^63) gets an error that
/// names the quantity, never a wrapped, negative count.
class ByteCounter {
public:
  explicit ByteCounter(SimulationOp simulation) : simulation(simulation) {}

  /// The product of `factors`, or an error naming `what`.
  FailureOr<int64_t> product(ArrayRef<int64_t> factors, const Twine &what) {
    int64_t result = 1;
    for (int64_t factor : factors) {
      std::optional<int64_t> next = llvm::checkedMul(result, factor);
      if (!next)
        return overflow(what);
      result = *next;
    }
    return result;
  }

  /// `total += value`, or an error naming `what`.
  LogicalResult add(int64_t &total, int64_t value, const Twine &what) {
    std::optional<int64_t> sum = llvm::checkedAdd(total, value);
    if (!sum)
      return overflow(what);
    total = *sum;
    return success();
  }

private:
  LogicalResult overflow(const Twine &what) {
    return simulation.emitOpError()
           << "needs more than " << std::numeric_limits<int64_t>::max()
           << " bytes for " << what << "; the memory report cannot count them";
  }

  SimulationOp simulation;
};

struct ReportMemoryPass
    : public sim::impl::SimReportMemoryBase<ReportMemoryPass> {
  using SimReportMemoryBase::SimReportMemoryBase;

  void runOnOperation() override {
    if (groupSize < 1) {
      // Located at the first scene (the module has no location of its own
      // in a file).
      Location loc = getOperation()->getLoc();
      getOperation()->walk([&](SimulationOp simulation) {
        loc = simulation.getLoc();
        return WalkResult::interrupt();
      });
      emitError(loc)
          << "--sim-report-memory needs a positive group-size, but got "
          << static_cast<int64_t>(groupSize);
      return signalPassFailure();
    }
    llvm::json::Array reports;
    WalkResult result = getOperation()->walk([&](SimulationOp simulation) {
      FailureOr<MemoryReport> report = build(simulation);
      if (failed(report))
        return WalkResult::interrupt();
      if (format == ReportFormat::json)
        reports.push_back(toJson(*report, groupSize));
      else
        printText(*report, groupSize, llvm::outs());
      return WalkResult::advance();
    });
    if (result.wasInterrupted())
      return signalPassFailure();
    if (format == ReportFormat::json)
      llvm::outs() << llvm::formatv("{0:2}",
                                    llvm::json::Value(std::move(reports)))
                   << "\n";
    llvm::outs().flush();
    markAllAnalysesPreserved();
  }

  FailureOr<MemoryReport> build(SimulationOp simulation) {
    StrategyAttr strategy = simulation.getStrategyAttr();
    if (!strategy)
      return simulation.emitOpError()
             << "has no memory plan; run --sim-plan-memory before "
                "--sim-report-memory";
    MemoryReport report;
    report.simulation = simulation.getSymName().str();
    report.strategy = stringifyStrategy(strategy.getValue()).str();
    report.range = simulation.getRange();
    ByteCounter counter(simulation);
    llvm::DenseMap<StringAttr, int64_t> elementBytes;
    for (BufferOp buffer : simulation.getBuffers()) {
      BufferRow row;
      row.name = buffer.getSymName().str();
      llvm::raw_string_ostream(row.type) << buffer.getElementType();
      row.elementBytes = buffer.getElementBytes();
      std::string items = std::to_string(report.range) + " items x " +
                          std::to_string(row.elementBytes) + " bytes";
      FailureOr<int64_t> halves = counter.product(
          {2, report.range, row.elementBytes},
          "the two halves of @" + row.name + " (2 x " + items + ")");
      if (failed(halves))
        return failure();
      FailureOr<int64_t> copies =
          counter.product({3, report.range, row.elementBytes},
                          "the naive plan's three copies of @" + row.name +
                              " (3 x " + items + ")");
      if (failed(copies))
        return failure();
      row.halvesBytes = *halves;
      // A snapshot is one copy: it fits when the two halves do, and the
      // total when the naive plan's three copies do.
      row.snapshotBytes = buffer.getSnapshot() ? *halves / 2 : 0;
      row.totalBytes = row.halvesBytes + row.snapshotBytes;
      if (failed(counter.add(report.plannedBytes, row.totalBytes,
                             "the planned device memory")) ||
          failed(counter.add(report.naiveBytes, *copies,
                             "the naive plan (3 copies of every buffer)")))
        return failure();
      elementBytes[buffer.getSymNameAttr()] = row.elementBytes;
      report.buffers.push_back(row);
    }
    for (ComponentOp component : simulation.getComponents()) {
      ArrayAttr caches = component.getCachesAttr();
      if (!caches)
        continue;
      // One element per thread of the group plus the window's halo.
      std::string what = "the shared-memory caches of @" +
                         component.getSymName().str() + " (group-size " +
                         std::to_string(groupSize) + ")";
      int64_t bytes = 0;
      for (auto cache : caches.getAsRange<CacheAttr>()) {
        int64_t elements = groupSize;
        if (failed(counter.add(elements, cache.getHalo(), what)))
          return failure();
        FailureOr<int64_t> cacheBytes = counter.product(
            {elements, elementBytes.lookup(cache.getBuffer().getAttr())}, what);
        if (failed(cacheBytes) || failed(counter.add(bytes, *cacheBytes, what)))
          return failure();
      }
      report.caches.push_back({component.getSymName().str(), bytes});
    }
    return report;
  }
};

} // namespace
