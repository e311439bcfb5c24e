//===- LocalStepKernels.cpp - local time steps of thread groups -----------===//
//
// For components that advance in `local_steps` (strategy `lts`,
// docs/Model.md, "Local time stepping"): every block of kLevelBlock (32)
// items takes its own power-of-two sub-step in the big step, so a stiff
// region no longer sets the step of the whole range. Blocks, not thread
// groups, so that the result does not depend on the group size and a
// stiff item holds back 32 items, not a whole group. The kernels, in launch
// order:
//
//   snapshot_B       the value at T of buffers later components read
//   levels_C         each block's minimum num_steps at T, and the unit
//                    request (the minimum over every item)
//   limit_levels_C   the unit u (the request, at most m) and each block's
//                    sub-step in units: the whole big step when its
//                    minimum is m or more, else the largest power of two
//                    within minimum / u (the whole step counts as M, the
//                    smallest power of two not below m / u, and every
//                    sub-step ends with the big step at the latest); then
//                    the largest with none more than twice a
//                    neighbour's; the finest; each block's
//                    neighbourhood codes. On a GPU one lane per block (a
//                    minimum over the blocks within ceil(log2 max_steps)
//                    neighbour steps, the finest by an atomic minimum); on
//                    a CPU one lane in one pass of sweeps, which also
//                    finds where each run of equal codes ends
//   max_steps times:
//     local_flux_E   (a flux pair, docs/Model.md "Conservation") every
//                    interface of the flux writer E whose coarsest reading
//                    block starts a sub-step at q: its flux from C's state
//                    at T + q, held until that block's next sub-step
//     local_step_C   slot q of the big step: every item whose block's
//                    sub-step divides q takes one sub-step from T + q; the
//                    invocation that finishes last moves the clock to the
//                    next slot, q + the finest sub-step
//   local_parity_C   blocks that took an even number of sub-steps copy
//                    their result into the target half
//
// `levels @C` has eight sections of one i64 per block: two halves of
// codes (the big step of clock parity p uses half p), two of
// neighbourhood codes (kLevelStepCodes, kLevelFluxCodes: the block's
// sub-step when every block its items reach has it, else minus it (step)
// or 0 (flux)), two of where each block's run of equal codes ends, so
// that a slot kernel decides from one value per run which blocks start at
// the slot and which of those read their neighbours in step (wide loads on
// a CPU) or through their time levels, and the blocks' sub-steps
// (kLevelSteps), and the codes kept for a component whose levels cannot
// change (kLevelCached, invariant_levels: levels_C then stops computing
// them, and the CPU's limit_levels_C limits them again only when m changes,
// keeping that m and the finest sub-step in the code halves, which nothing
// else uses then). levels_C combines its items into half p with an atomic
// maximum of kLevelCode - min(num_steps, max_steps) (0, what the runtime and
// limit_levels_C of the previous big step leave there, is the identity);
// limit_levels_C turns the codes into sub-steps (the largest power of two
// not above the block's minimum, capped at m, once per block rather than per
// item: rounding down commutes with the minimum), limits them, clears half 1 -
// p for the next big step and writes the codes and runs. On a GPU every block's
// work is its own, spread over the lanes of an items launch: one thread walking
// the blocks would cost a dependent load per block and sweep per big step. The
// sub-step clock of the component holds: Begin, the time T + q of the next slot
// (advance resets it to T); Size, the finest sub-step in units; Done, the
// invocations of local_step_C that finished the slot so far (0 between
// launches); Unit, the big step's unit u (limit_levels_C); UnitRequest,
// what levels_C combines u from. Which half
// of a buffer holds a block's latest level follows from its sub-step and the
// slot alone, so no flag is written during a slot and every reader can
// tell (KernelBody.cpp, the `local` loads).
//
//===----------------------------------------------------------------------===//

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "sim/Conversion/SimCommon/KernelNames.h"
#include "sim/Conversion/SimCommon/SimulationLowering.h"

#include <array>

using namespace mlir;
using namespace mlir::sim;

ComponentOp SimulationLowering::findFluxWriter(ComponentOp reader) {
  for (ComponentOp writer : order) {
    if (writer.getAdvance() != Advance::local_flux)
      continue;
    auto writes = writer.getWrites().getAsRange<FlatSymbolRefAttr>();
    WalkResult found = reader.getEvaluate().walk([&](LoadOp load) {
      return llvm::is_contained(writes, load.getBufferAttr())
                 ? WalkResult::interrupt()
                 : WalkResult::advance();
    });
    if (found.wasInterrupted())
      return writer;
  }
  return nullptr;
}

LogicalResult SimulationLowering::emitLocalSteps(ComponentOp component,
                                                 OpBuilder &launches) {
  int64_t sub = subClockSlots.lookup(component);
  StringRef name = component.getSymName();
  StringAttr symbol = component.getSymNameAttr();
  auto writes =
      llvm::to_vector(component.getWrites().getAsRange<FlatSymbolRefAttr>());
  ArrayRef<int64_t> window = component.getLocalWindowAttr().asArrayRef();
  int64_t reach = std::max(-window[0], window[1]);
  // The windows of its reads whose blocks decide whether a block's
  // neighbourhood is in step: the recorded ones where they leave gaps
  // (local_reads: a stencil on a flattened grid), else the whole reach on
  // each side.
  SmallVector<std::pair<int64_t, int64_t>> readWindows;
  DenseI64ArrayAttr localReads = component.getLocalReadsAttr();
  if (localReads)
    for (int64_t k = 0; k + 1 < localReads.size(); k += 2)
      readWindows.emplace_back(localReads[k], localReads[k + 1]);
  else
    readWindows.emplace_back(-reach, reach);
  // Blocks within `radius` of a block are its neighbours: those its window
  // can reach. They wrap around the range when a buffer it writes does.
  int64_t radius = llvm::divideCeil(reach, kLevelBlock);
  bool cyclic = llvm::any_of(writes, [&](FlatSymbolRefAttr write) {
    return simulation.lookupBuffer(write).getBoundary() == Boundary::wrap;
  });
  component.emitRemark()
      << "@" << name << " takes local time steps: every block of "
      << kLevelBlock
      << " items its own sub-step (the whole big step, or the finest "
         "num_steps times a power of two below it), at most twice that of the "
      << radius << " block" << (radius == 1 ? "" : "s")
      << " on each side, in up to " << maxSteps
      << " slot launches per big step";

  if (failed(emitSnapshots(component, launches)))
    return failure();

  // The blocks of the range and the half of `levels @C` of this big step.
  auto blocksOf = [&](Kernel &kernel) {
    return arith::DivUIOp::create(
               b, b.loc, b.add(kernel.values.range, b.index(kLevelBlock - 1)),
               b.index(kLevelBlock))
        .getResult();
  };
  auto blockOf = [&](Value item) {
    return arith::DivUIOp::create(b, b.loc, item, b.index(kLevelBlock))
        .getResult();
  };

  // Sub-steps are powers of two: masks instead of divisions. A block of
  // sub-step `level` starts one at `slot` when the slot is a multiple of
  // it, after slot / level sub-steps, whose parity (bit `level` of the
  // slot) selects the half it reads (`parity` is the big step's).
  auto startsAt = [&](Value slot, Value level) {
    return b.cmp(arith::CmpIPredicate::eq,
                 arith::AndIOp::create(b, b.loc, slot, b.sub(level, b.i64(1))),
                 b.i64(0));
  };
  auto readParityOf = [&](Value parity, Value slot, Value level) {
    Value odd =
        b.extend(b.cmp(arith::CmpIPredicate::ne,
                       arith::AndIOp::create(b, b.loc, slot, level), b.i64(0)),
                 b.getI64Type());
    return arith::XOrIOp::create(b, b.loc, parity, odd).getResult();
  };
  // The sub-step that stands for the whole big step `size` (m >= 1 where
  // used): the smallest power of two not below it, so that every sub-step
  // is a power of two (docs/Model.md, "Levels"). With m a power of two it
  // is m.
  auto wholeStepOf = [&](Value size) {
    Value atLeastOne = b.max(size, b.i64(1));
    return b.floorPowerOfTwo(b.sub(b.add(atLeastOne, atLeastOne), b.i64(1)));
  };

  // Sub-steps are counted in the big step's unit `u` of base steps (the
  // sub-step clock's Unit, which limit_levels_C sets): a block of sub-step
  // `level` units takes `level * u` base steps, and the slots lie `u`
  // apart. With every request a power of two or m or more, `u` is 1 or m.
  // At least 1: a clock that has not limited levels yet holds none.
  auto unitOf = [&](Kernel &kernel) {
    return b.max(b.load(kernel.clock, b.index(sub + kSubUnit)), b.i64(1));
  };
  // `steps` base steps in units, rounded up (the last sub-step may be
  // shorter than a unit: it ends with the big step).
  auto unitsOf = [&](Value steps, Value unit) {
    return arith::DivUIOp::create(b, b.loc, b.add(steps, b.sub(unit, b.i64(1))),
                                  unit)
        .getResult();
  };
  // The length in base steps of a sub-step of `level` units that starts
  // `offset` base steps into the big step `size`: the last one of a block
  // ends with the big step.
  auto lengthOf = [&](Value level, Value unit, Value offset, Value size) {
    return b.min(b.mul(level, unit), b.sub(size, offset));
  };
  // The neighbourhood codes of the blocks of a part (limit_levels_C): whether
  // they are all one code, and the first. A part inside the range.
  auto partCode = [&](Kernel &kernel, Value levels, Value codes,
                      const Part &part) -> std::pair<Value, Value> {
    Value end = b.min(b.add(part.base, part.count), kernel.values.range);
    Value firstBlock = blockOf(part.base);
    Value endBlock = b.add(blockOf(b.sub(end, b.index(1))), b.index(1));
    Value first = b.load(levels, b.add(codes, firstBlock));
    auto scan = scf::ForOp::create(b, b.loc, b.add(firstBlock, b.index(1)),
                                   endBlock, b.index(1),
                                   ValueRange{b.constant(b.getI1Type(), 1)});
    OpBuilder::InsertionGuard guard(b);
    b.setInsertionPointToStart(scan.getBody());
    Value same =
        b.cmp(arith::CmpIPredicate::eq,
              b.load(levels, b.add(codes, scan.getInductionVar())), first);
    scf::YieldOp::create(
        b, b.loc,
        arith::AndIOp::create(b, b.loc, scan.getRegionIterArg(0), same)
            .getResult());
    return {scan.getResult(0), first};
  };

  // The prologue of a slot kernel: the big step, `levels @C`, the slot's
  // time `now = T + offset`, the unit, the slot `offset / unit` and the big
  // step `units` in units, and whether a slot of this big step is due.
  struct Slot {
    Value begin, size, parity, levels, dt, now, offset, unit, slot, units,
        running;
  };
  auto readSlot = [&](Kernel &kernel) {
    Slot state;
    readBigStep(kernel, state.begin, state.size, state.parity);
    state.levels = kernel.levels.lookup(symbol);
    state.dt = kernel.values.params.lookup("dt");
    state.now = b.load(kernel.clock, b.index(sub + kSubBegin));
    state.offset = b.sub(state.now, state.begin);
    state.unit = unitOf(kernel);
    state.slot =
        arith::DivUIOp::create(b, b.loc, state.offset, state.unit).getResult();
    state.units = unitsOf(state.size, state.unit);
    state.running = arith::AndIOp::create(
        b, b.loc, b.cmp(arith::CmpIPredicate::sgt, state.size, b.i64(0)),
        b.cmp(arith::CmpIPredicate::slt, state.offset, state.size));
    return state;
  };
  // `evaluated`'s evaluate body at a lane's item over its sub-step of
  // `level` units from the slot: from `now`, over its length in base steps.
  auto evaluateSubStep = [&](ComponentOp evaluated, const Slot &state,
                             const Lane &lane, Value level,
                             KernelValues &values) {
    Value length = b.truncate(
        lengthOf(level, state.unit, state.offset, state.size), b.getI32Type());
    return inline_(evaluated.getEvaluate(),
                   {lane.item, state.now, length, state.dt}, values);
  };
  // The results of a lane's evaluation into the half at `base` and
  // `parity` of the buffers `writes`, and one more evaluation in `count`
  // (unless null: a run counts its lanes at once).
  auto storeResults =
      [&](Kernel &kernel, const Lane &lane, ArrayRef<FlatSymbolRefAttr> writes,
          ArrayRef<Value> results, Value base, Value parity, LaneVar *count) {
        for (auto [write, value] : llvm::zip_equal(writes, results))
          b.store(value, kernel.values.buffers.lookup(write.getAttr()),
                  at(kernel, write.getAttr(), base, parity, lane.item));
        if (count)
          target.laneStore(b, b.add(target.laneLoad(b, *count, lane), b.i32(1)),
                           *count, lane);
      };
  // The index range [begin, end) piece by piece (an scf.while): `piece`
  // takes the start of a piece and returns where it stops, the next start.
  auto forEachPiece = [&](Value begin, Value end,
                          function_ref<Value(Value)> piece) {
    auto loop =
        scf::WhileOp::create(b, b.loc, b.getIndexType(), ValueRange{begin});
    OpBuilder::InsertionGuard guard(b);
    Block *before =
        b.createBlock(&loop.getBefore(), {}, b.getIndexType(), b.loc);
    scf::ConditionOp::create(
        b, b.loc, b.cmp(arith::CmpIPredicate::ult, before->getArgument(0), end),
        before->getArguments());
    Block *after = b.createBlock(&loop.getAfter(), {}, b.getIndexType(), b.loc);
    scf::YieldOp::create(b, b.loc, piece(after->getArgument(0)));
  };
  // The items of `part` block by block: `body(start, block, stop)` for the
  // items [start, stop) of the part in block `block` (index values).
  auto forEachBlockOf = [&](const Part &part,
                            function_ref<void(Value, Value, Value)> body) {
    Value end = b.add(part.base, part.count);
    forEachPiece(part.base, end, [&](Value start) {
      Value block = blockOf(start);
      Value stop =
          b.min(b.mul(b.add(block, b.index(1)), b.index(kLevelBlock)), end);
      body(start, block, stop);
      return stop;
    });
  };
  // The parts of the groups of a kernel with their codes of section
  // `codeSection` (partCode): `forPart(part, same, code, origin)`. Where the
  // target splits groups, a part is a run of blocks of one code (its end
  // in `runSection`), walked over all the groups of the invocation (`origin`
  // is the first item of the first; the part's lanes are numbered from 0,
  // so no lane variable may be indexed by them: piecesOf splits it into
  // groups for that), `same` is true, and a run that `due(code)` says has
  // nothing to do is skipped with one test. Else a part is the whole group
  // and `origin` is null.
  auto forEachCodePart =
      [&](Kernel &kernel, Value levels, int64_t codeSection, int64_t runSection,
          function_ref<Value(Value)> due,
          function_ref<void(const Part &, Value, Value, Value)> forPart) {
        Value blocks = blocksOf(kernel);
        Value codes = b.mul(b.index(codeSection), blocks);
        Value runs = b.mul(b.index(runSection), blocks);
        Value range = kernel.values.range;
        if (!target.splitsGroups()) {
          target.forEachGroup(b, kernel, [&](Value groupBase) {
            b.ifThen(b.cmp(arith::CmpIPredicate::ult, groupBase, range), [&] {
              Part part{groupBase, b.index(0), target.groupSize(b, kernel),
                        /*whole=*/true};
              Value same, code;
              std::tie(same, code) = partCode(kernel, levels, codes, part);
              forPart(part, same, code, Value());
            });
          });
          return;
        }
        target.forEachGroupSpan(b, kernel, [&](Value origin, Value spanEnd) {
          forEachPiece(origin, spanEnd, [&](Value start) {
            Value block = blockOf(start);
            Value code = b.load(levels, b.add(codes, block));
            Value runEnd =
                b.min(b.mul(b.toIndex(b.load(levels, b.add(runs, block))),
                            b.index(kLevelBlock)),
                      spanEnd);
            b.ifThen(due(code), [&] {
              forPart(Part{start, b.index(0), b.sub(runEnd, start),
                           /*whole=*/false},
                      b.constant(b.getI1Type(), 1), code, origin);
            });
            return runEnd;
          });
        });
      };
  // The pieces of a run (forEachCodePart) in each group, their lanes
  // numbered as the group's.
  auto piecesOf = [&](Kernel &kernel, const Part &run, Value origin,
                      function_ref<void(const Part &)> body) {
    Value size = target.groupSize(b, kernel);
    Value runEnd = b.add(run.base, run.count);
    forEachPiece(run.base, runEnd, [&](Value piece) {
      Value offset = b.sub(piece, origin);
      Value groupBase = b.add(
          origin, b.mul(arith::DivUIOp::create(b, b.loc, offset, size), size));
      Value end = b.min(b.add(groupBase, size), runEnd);
      body(Part{piece, b.sub(piece, groupBase), b.sub(end, piece),
                /*whole=*/false});
      return end;
    });
  };

  // The lanes of a slot kernel, part by part: `inStep(lane, level,
  // readParity)` for every lane of a part whose blocks all have the positive
  // neighbourhood code `level` (their neighbourhood is in step at that
  // sub-step) when it starts at the slot, `general(lane)` for every lane of
  // any other part. A negative code is minus a sub-step that every item of
  // its block takes (step codes: the block's own) or divides (flux codes:
  // the finest its interfaces reach), so a part whose blocks all have one
  // that does not start at the slot has nothing to do. A part is a run of
  // blocks of one code where the target splits groups (KernelTarget::
  // splitsGroups: one test skips the run, one loop of SIMD chunks runs it),
  // else the whole group. Where a part is a run, `repair(lane, level,
  // readParity)` (unless null) evaluates a lane of a run whose blocks all
  // take the sub-step `level` (a negative step code) through the time
  // levels, uncounted, instead of `general`, which finds each lane's own.
  auto forEachPartAtSlot =
      [&](Kernel &kernel, Value levels, int64_t codeSection, int64_t runSection,
          Value slot, Value parity, int64_t countSlot,
          function_ref<void(const Lane &, Value, Value, bool)> inStep,
          function_ref<void(const Lane &)> general,
          function_ref<void(const Lane &, Value, Value)> repair,
          int64_t interiorBelow = -1, int64_t interiorAbove = -1) {
        Value blocks = blocksOf(kernel);
        Value range = kernel.values.range;
        auto forPart = [&](const Part &part, Value same, Value code,
                           Value origin) {
          auto lanesOf = [&](const Part &lanes,
                             function_ref<void(const Lane &)> body) {
            target.forEachLaneOf(b, kernel, lanes, [&](const Lane &lane) {
              b.ifThen(lane.active, [&] { body(lane); });
            });
          };
          // Lanes that count their evaluations in a lane variable: a run's
          // pieces in each group.
          auto countingLanes = [&](function_ref<void(const Lane &)> body) {
            if (!origin)
              return lanesOf(part, body);
            piecesOf(kernel, part, origin,
                     [&](const Part &piece) { lanesOf(piece, body); });
          };
          // Every lane of the part takes its sub-step in step. A run's lanes
          // (all inside the range) run as one loop, counted at once.
          auto allInStep = [&](Value level, Value readParity) {
            if (!origin)
              return lanesOf(part, [&](const Lane &lane) {
                inStep(lane, level, readParity, /*counted=*/true);
              });
            lanesOf(part, [&](const Lane &lane) {
              inStep(lane, level, readParity, /*counted=*/false);
            });
            b.atomic(arith::AtomicRMWKind::addi,
                     arith::IndexCastOp::create(b, b.loc, b.getI64Type(),
                                                part.count),
                     kernel.clock, b.index(countSlot));
          };
          Value inStepHere = arith::AndIOp::create(
              b, b.loc, same, b.cmp(arith::CmpIPredicate::sgt, code, b.i64(0)));
          auto branch = scf::IfOp::create(b, b.loc, TypeRange{}, inStepHere,
                                          /*withElseRegion=*/true);
          OpBuilder::InsertionGuard guard(b);
          b.setInsertionPointToStart(branch.thenBlock());
          b.ifThen(startsAt(slot, code),
                   [&] { allInStep(code, readParityOf(parity, slot, code)); });
          b.setInsertionPointToStart(branch.elseBlock());
          if (origin && repair) {
            // A run of one sub-step whose neighbourhood is not. Its lanes
            // share the sub-step and the half they read and write, so only
            // their reads of other items need the time levels. With a
            // window of at most a block only its first and last `reach`
            // items read another block: the whole run takes its sub-step
            // in step (SIMD chunks), then `repair` evaluates again,
            // through the time levels, the items at an end whose next
            // block has another sub-step (or that wrap around the range).
            // Nothing reads the half a block writes in its own slot (its
            // readers' latest level of it is the other half), so the first
            // results are never seen. A wider window, or a run shorter
            // than two windows, evaluates every lane once through the time
            // levels (`repair`, counted at once), block by block. Either
            // way a neighbour block that is aligned at the slot (`aligned`
            // below) reads as in step: at slot 0 every block is.
            Value level = b.sub(b.i64(0), code);
            b.ifThen(startsAt(slot, level), [&] {
              Value readParity = readParityOf(parity, slot, level);
              Value half = b.mul(b.index(kLevelSteps), blocks);
              // Whether block h's latest level is at the slot and in the
              // half the run reads: then a read of it through the time
              // levels returns that half's value as is (docs/Model.md,
              // "What a read returns", t = b), so a plain read gives the
              // same bits. At slot 0 every block is; a coarser block is
              // at every other slot of its own.
              auto aligned = [&](Value h) {
                Value other = b.load(levels, b.add(half, h));
                return arith::AndIOp::create(
                           b, b.loc, startsAt(slot, other),
                           b.cmp(arith::CmpIPredicate::eq,
                                 readParityOf(parity, slot, other), readParity))
                    .getResult();
              };
              auto both = [&](Value x, Value y) {
                return arith::AndIOp::create(b, b.loc, x, y).getResult();
              };
              // Every lane once through the time levels, counted at once;
              // but a block whose window reaches only aligned blocks
              // inside the range (or clamped into it) reads in step.
              auto throughLevels = [&] {
                forEachBlockOf(part, [&](Value start, Value block, Value stop) {
                  Value firstItem = b.mul(block, b.index(kLevelBlock));
                  Value zero = b.index(0), last = b.sub(range, b.index(1));
                  Value lastItem =
                      b.min(b.add(firstItem, b.index(kLevelBlock - 1)), last);
                  Value readsAligned;
                  if (!localReads) {
                    Value below = b.index(std::max<int64_t>(-window[0], 0));
                    Value above = b.index(std::max<int64_t>(window[1], 0));
                    Value inside = b.constant(b.getI1Type(), 1);
                    if (cyclic)
                      inside = both(
                          b.cmp(arith::CmpIPredicate::uge, firstItem, below),
                          b.cmp(arith::CmpIPredicate::ult,
                                b.add(lastItem, above), range));
                    Value low = b.select(
                        b.cmp(arith::CmpIPredicate::uge, firstItem, below),
                        b.sub(firstItem, below), zero);
                    Value high = b.min(b.add(lastItem, above), last);
                    auto scan =
                        scf::ForOp::create(b, b.loc, blockOf(low),
                                           b.add(blockOf(high), b.index(1)),
                                           b.index(1), ValueRange{inside});
                    OpBuilder::InsertionGuard inner(b);
                    b.setInsertionPointToStart(scan.getBody());
                    scf::YieldOp::create(b, b.loc,
                                         both(scan.getRegionIterArg(0),
                                              aligned(scan.getInductionVar())));
                    readsAligned = scan.getResult(0);
                  } else {
                    // Only the blocks its reads reach: of each window, the
                    // items from its first item's to its last item's read,
                    // clamped into the range (none outside it under wrap).
                    readsAligned = b.constant(b.getI1Type(), 1);
                    auto asI64 = [&](Value index) -> Value {
                      return arith::IndexCastOp::create(b, b.loc,
                                                        b.getI64Type(), index);
                    };
                    Value firstI64 = asI64(firstItem),
                          lastI64 = asI64(lastItem);
                    Value zero64 = b.i64(0), range64 = asI64(range);
                    Value lastOfRange = b.sub(range64, b.i64(1));
                    auto clamp = [&](Value item) {
                      return b.toIndex(b.min(b.max(item, zero64), lastOfRange));
                    };
                    for (auto [lo, hi] : readWindows) {
                      Value lowItem = b.add(firstI64, b.i64(lo));
                      Value highItem = b.add(lastI64, b.i64(hi));
                      if (cyclic)
                        readsAligned = both(
                            readsAligned, both(b.cmp(arith::CmpIPredicate::sge,
                                                     lowItem, zero64),
                                               b.cmp(arith::CmpIPredicate::slt,
                                                     highItem, range64)));
                      auto reads = scf::ForOp::create(
                          b, b.loc, blockOf(clamp(lowItem)),
                          b.add(blockOf(clamp(highItem)), b.index(1)),
                          b.index(1), ValueRange{readsAligned});
                      OpBuilder::InsertionGuard inner(b);
                      b.setInsertionPointToStart(reads.getBody());
                      scf::YieldOp::create(
                          b, b.loc,
                          both(reads.getRegionIterArg(0),
                               aligned(reads.getInductionVar())));
                      readsAligned = reads.getResult(0);
                    }
                  }
                  Part piece{start, b.add(part.first, b.sub(start, part.base)),
                             b.sub(stop, start), /*whole=*/false};
                  auto branch =
                      scf::IfOp::create(b, b.loc, TypeRange{}, readsAligned,
                                        /*withElseRegion=*/true);
                  OpBuilder::InsertionGuard inner(b);
                  b.setInsertionPointToStart(branch.thenBlock());
                  lanesOf(piece, [&](const Lane &lane) {
                    inStep(lane, level, readParity, /*counted=*/false);
                  });
                  b.setInsertionPointToStart(branch.elseBlock());
                  lanesOf(piece, [&](const Lane &lane) {
                    repair(lane, level, readParity);
                  });
                });
                b.atomic(arith::AtomicRMWKind::addi,
                         arith::IndexCastOp::create(b, b.loc, b.getI64Type(),
                                                    part.count),
                         kernel.clock, b.index(countSlot));
              };
              if (reach > kLevelBlock)
                return throughLevels();
              Value wide = b.cmp(arith::CmpIPredicate::uge, part.count,
                                 b.index(2 * reach));
              auto split = scf::IfOp::create(b, b.loc, TypeRange{}, wide,
                                             /*withElseRegion=*/true);
              OpBuilder::InsertionGuard inner(b);
              b.setInsertionPointToStart(split.thenBlock());
              allInStep(level, readParity);
              // The items within `reach` before the part (and after it)
              // lie in at most two blocks: those of the first and the last
              // of them; when either has another sub-step, or they wrap
              // around the range, the part's first (last) `reach` items
              // are repaired. (A part may start or end inside a run, at a
              // group's edge: its neighbours there are then in step.)
              // An item of an aligned block reads as in step.
              auto otherLevel = [&](Value item) {
                return b.xorOne(aligned(blockOf(item)));
              };
              auto either = [&](Value x, Value y) {
                return arith::OrIOp::create(b, b.loc, x, y).getResult();
              };
              Value zero = b.index(0), edge = b.index(reach);
              Value end = b.add(part.base, part.count);
              Value last = b.sub(range, b.index(1));
              // Whether the items within `reach` beyond one end of the part
              // (`near` and `far` the blocks' items, `outside` whether they
              // leave the range) need a repair; at an end of the range only
              // a wrap reads beyond it.
              auto beyond = [&](Value atRangeEnd,
                                function_ref<std::array<Value, 3>()> items) {
                return b
                    .ifThenElse(
                        b.getI1Type(), atRangeEnd,
                        [&]() -> SmallVector<Value> {
                          return {b.constant(b.getI1Type(), cyclic)};
                        },
                        [&]() -> SmallVector<Value> {
                          auto [near, far, outside] = items();
                          Value other =
                              either(otherLevel(near), otherLevel(far));
                          return {cyclic ? either(other, outside) : other};
                        })
                    .getResult(0);
              };
              Value repairFirst =
                  beyond(b.cmp(arith::CmpIPredicate::eq, part.base, zero), [&] {
                    Value outside =
                        b.cmp(arith::CmpIPredicate::ult, part.base, edge);
                    Value low = b.select(outside, zero, b.sub(part.base, edge));
                    return std::array<Value, 3>{b.sub(part.base, b.index(1)),
                                                low, outside};
                  });
              Value repairLast =
                  beyond(b.cmp(arith::CmpIPredicate::eq, end, range), [&] {
                    Value high = b.add(end, b.index(reach - 1));
                    return std::array<Value, 3>{
                        end, b.min(high, last),
                        b.cmp(arith::CmpIPredicate::ugt, high, last)};
                  });
              auto repairLanes = [&](Value offset) {
                lanesOf(
                    Part{b.add(part.base, offset), b.add(part.first, offset),
                         edge,
                         /*whole=*/false},
                    [&](const Lane &lane) { repair(lane, level, readParity); });
              };
              b.ifThen(repairFirst, [&] { repairLanes(b.index(0)); });
              b.ifThen(repairLast,
                       [&] { repairLanes(b.sub(part.count, edge)); });
              b.setInsertionPointToStart(split.elseBlock());
              throughLevels();
            });
            return;
          }
          if (origin && interiorBelow >= 0 &&
              interiorBelow + interiorAbove < kLevelBlock) {
            // A run of a flux writer's interfaces whose neighbourhood is
            // not in step: the interfaces of a block whose readers and
            // state lie in the block (all but `interiorBelow` at its start
            // and `interiorAbove` at its end) take the block's sub-step and
            // read it in step, so they run as SIMD chunks at the slots
            // where the block starts one; the others take the general
            // path, which finds each one's sub-step. The same evaluations
            // as the general path for every interface.
            b.ifThen(startsAt(slot, b.sub(b.i64(0), code)), [&] {
              Value half = b.mul(b.index(kLevelSteps), blocks);
              auto generalLanes = [&](Value from, Value to) {
                b.ifThen(b.cmp(arith::CmpIPredicate::ult, from, to), [&] {
                  piecesOf(kernel,
                           Part{from, b.index(0), b.sub(to, from),
                                /*whole=*/false},
                           origin,
                           [&](const Part &piece) { lanesOf(piece, general); });
                });
              };
              forEachBlockOf(part, [&](Value start, Value block, Value stop) {
                Value blockStart = b.mul(block, b.index(kLevelBlock));
                Value blockEnd =
                    b.min(b.add(blockStart, b.index(kLevelBlock)), range);
                Value low = b.min(
                    b.max(start, b.add(blockStart, b.index(interiorBelow))),
                    stop);
                // blockEnd - interiorAbove, not below `low`.
                Value high = b.max(
                    low,
                    b.min(stop, b.sub(b.max(blockEnd, b.index(interiorAbove)),
                                      b.index(interiorAbove))));
                Value level = b.load(levels, b.add(half, block));
                Value interior = arith::AndIOp::create(
                    b, b.loc, b.cmp(arith::CmpIPredicate::ult, low, high),
                    startsAt(slot, level));
                b.ifThen(interior, [&] {
                  Value readParity = readParityOf(parity, slot, level);
                  lanesOf(Part{low, b.index(0), b.sub(high, low),
                               /*whole=*/false},
                          [&](const Lane &lane) {
                            inStep(lane, level, readParity,
                                   /*counted=*/false);
                          });
                  b.atomic(arith::AtomicRMWKind::addi,
                           arith::IndexCastOp::create(b, b.loc, b.getI64Type(),
                                                      b.sub(high, low)),
                           kernel.clock, b.index(countSlot));
                });
                generalLanes(start, low);
                generalLanes(high, stop);
              });
            });
            return;
          }
          Value due = arith::OrIOp::create(
              b, b.loc, b.xorOne(same), startsAt(slot, b.sub(b.i64(0), code)));
          b.ifThen(due, [&] { countingLanes(general); });
        };
        forEachCodePart(
            kernel, levels, codeSection, runSection,
            [&](Value code) -> Value {
              // A negative code is minus a sub-step that every item of the
              // run takes or (flux) divides.
              return startsAt(slot, b.max(code, b.sub(b.i64(0), code)));
            },
            forPart);
      };

  // A flux pair: the items that read interface `j` of the writer's fluxes
  // are `j - o` for the offsets `o` of flux_window, under the fluxes'
  // boundary rule (around the range under wrap, the end item under clamp,
  // none outside the range under zero). `withReader` gets each reader and
  // whether it exists.
  ComponentOp fluxWriter = findFluxWriter(component);
  // `combine` folds each reader, and whether it exists, into `init`.
  auto foldReaders = [&](Kernel &kernel, Value interface, Value init,
                         function_ref<Value(Value, Value, Value)> combine) {
    ArrayRef<int64_t> offsets = fluxWriter.getFluxWindowAttr().asArrayRef();
    BufferOp flux = simulation.lookupBuffer(
        cast<FlatSymbolRefAttr>(fluxWriter.getWrites()[0]));
    Value range = kernel.values.range;
    auto loop = scf::ForOp::create(b, b.loc, b.index(offsets[0]),
                                   b.index(offsets[1] + 1), b.index(1),
                                   ValueRange{init});
    OpBuilder::InsertionGuard guard(b);
    b.setInsertionPointToStart(loop.getBody());
    Value reader = b.sub(interface, loop.getInductionVar());
    Value zero = b.index(0), last = b.sub(range, b.index(1));
    Value exists = b.constant(b.getI1Type(), 1);
    switch (flux.getBoundary()) {
    case Boundary::wrap: {
      // As a window read wraps: a remainder only outside the range.
      Value unused;
      reader = buildBoundaryItem(b, b.loc, flux.getBoundary(), reader, range,
                                 unused);
      break;
    }
    case Boundary::clamp:
      reader = b.min(b.max(reader, zero), last);
      break;
    case Boundary::zero:
      exists = arith::AndIOp::create(
          b, b.loc, b.cmp(arith::CmpIPredicate::sge, reader, zero),
          b.cmp(arith::CmpIPredicate::slt, reader, range));
      reader = b.min(b.max(reader, zero), last);
      break;
    }
    scf::YieldOp::create(b, b.loc,
                         combine(reader, exists, loop.getRegionIterArg(0)));
    return loop.getResult(0);
  };

  // The items a block of a flux writer's interfaces reaches: their readers
  // (flux_window) and the state the writer reads (its local_window).
  int64_t fluxBelow = 0, fluxAbove = 0;
  if (fluxWriter) {
    ArrayRef<int64_t> fluxWindow = fluxWriter.getFluxWindowAttr().asArrayRef();
    ArrayRef<int64_t> stateWindow =
        fluxWriter.getLocalWindowAttr().asArrayRef();
    fluxBelow = std::max({int64_t(0), -stateWindow[0], fluxWindow[1]});
    fluxAbove = std::max({int64_t(0), stateWindow[1], -fluxWindow[0]});
  }

  // levels_C: each block's sub-step from its items' num_steps at T.
  {
    Kernel kernel = beginKernel(getKernelName(kernels, "levels", name));
    // No initial value: every active lane stores its code before
    // maxPerBlock reads the active lanes' codes, and on a CPU a group's
    // worth of zeros cost a memset in every big step, kept codes or not.
    LaneVar code = target.createLaneVar(b, kernel, b.getI64Type(), Value());
    // Each lane's smallest num_steps less kUnitBias (the unit request,
    // limit_levels_C's unit), combined into the sub-step clock by a
    // minimum; 0, the identity, in lanes that computed none.
    LaneVar request = target.createLaneVar(b, kernel, b.getI32Type(), b.i32(0));
    Value begin, size, parity;
    readBigStep(kernel, begin, size, parity);
    Value levels = kernel.levels.lookup(symbol);
    b.ifThen(b.cmp(arith::CmpIPredicate::sgt, size, b.i64(0)), [&] {
      Value half = b.mul(b.toIndex(parity), blocksOf(kernel));
      // The code of `writer`'s num_steps at T at a lane's item, capped at
      // max_steps rather than at m: limit_levels_C caps what it decodes at
      // m, so the codes hold for any big step (and can be kept, below).
      // It also joins the lane's unit request: the capped num_steps, at
      // least 1, less kUnitBias (an i32: num_steps is one).
      auto codeAt = [&](ComponentOp writer, const Lane &lane) {
        KernelValues values = kernel.values;
        values.item = lane.item;
        Value steps32 = estimate(kernel, writer, lane.item, begin, values);
        Value steps = b.extend(steps32, b.getI64Type());
        Value wanted =
            b.sub(b.max(b.min(steps32, b.i32(std::min(maxSteps, kUnitBias))),
                        b.i32(1)),
                  b.i32(kUnitBias));
        target.laneStore(b, b.min(target.laneLoad(b, request, lane), wanted),
                         request, lane);
        return b.sub(b.i64(kLevelCode), b.min(steps, b.i64(maxSteps)));
      };
      // Where limit_levels_C takes the finest sub-step by an atomic
      // minimum (one lane per block), it starts from m, set here (a launch
      // earlier) by the lane of the launch's first item.
      Value firstItem = kernel.values.first ? kernel.values.first : b.index(0);
      auto startFinest = [&](const Lane &lane) {
        if (target.limitsLevelsPerLane())
          b.ifThen(
              arith::AndIOp::create(
                  b, b.loc, lane.active,
                  b.cmp(arith::CmpIPredicate::eq, lane.item, firstItem)),
              [&] { b.store(size, kernel.clock, b.index(sub + kSubSize)); });
      };
      // Every lane's codes, combined per block into half `parity`.
      auto computeCodes = [&](Value base) {
        // (A pair's reader without num_steps: its writer's codes alone.)
        target.forEachLane(b, kernel, base, [&](const Lane &lane) {
          if (component.hasNumSteps())
            b.ifThen(lane.active, [&] {
              target.laneStore(b, codeAt(component, lane), code, lane);
            });
          startFinest(lane);
        });
        // Where no flux writer's estimate joins them, these codes are the
        // only writes of the launch to their blocks.
        bool fluxCodes = fluxWriter && fluxWriter.hasNumSteps();
        if (component.hasNumSteps())
          target.maxPerBlock(b, kernel, base, code, kLevelBlock, levels, half,
                             0, 0, /*onlyWriter=*/!fluxCodes);
        // A flux writer's estimate at interface j bounds every block that
        // reads the interface: the blocks of its readers j - o (o in
        // flux_window) that lie in the range, combined per block like the
        // codes above (so that the lanes' phase has no atomic); and, under
        // clamp or wrap, the readers that rule gives for those outside it,
        // one atomic each (the few interfaces at the ends of the range;
        // their readers inside the range again, which changes nothing).
        if (!fluxCodes)
          return;
        target.forEachLane(b, kernel, base, [&](const Lane &lane) {
          b.ifThen(lane.active, [&] {
            target.laneStore(b, codeAt(fluxWriter, lane), code, lane);
          });
        });
        ArrayRef<int64_t> offsets = fluxWriter.getFluxWindowAttr().asArrayRef();
        target.maxPerBlock(b, kernel, base, code, kLevelBlock, levels, half,
                           offsets[0], offsets[1]);
        BufferOp flux = simulation.lookupBuffer(
            cast<FlatSymbolRefAttr>(fluxWriter.getWrites()[0]));
        if (flux.getBoundary() == Boundary::zero)
          return;
        // Interface j has a reader outside the range unless
        // max(o1, 0) <= j < range + min(o0, 0).
        Value range = kernel.values.range;
        auto inside = [&](Value item) {
          Value above = b.cmp(arith::CmpIPredicate::sge, item,
                              b.index(std::max<int64_t>(offsets[1], 0)));
          Value below = b.cmp(arith::CmpIPredicate::slt, item,
                              b.add(range, b.index(offsets[0])));
          return arith::AndIOp::create(b, b.loc, above, below).getResult();
        };
        Value groupEnd = b.add(base, target.groupSize(b, kernel));
        Value atRangeEnds = arith::OrIOp::create(
            b, b.loc, b.xorOne(inside(base)),
            b.xorOne(inside(b.sub(b.min(groupEnd, range), b.index(1)))));
        b.ifThen(atRangeEnds, [&] {
          target.forEachLane(b, kernel, base, [&](const Lane &lane) {
            Value edge = arith::AndIOp::create(b, b.loc, lane.active,
                                               b.xorOne(inside(lane.item)));
            b.ifThen(edge, [&] {
              Value fluxCode = target.laneLoad(b, code, lane);
              foldReaders(kernel, lane.item, b.i64(0),
                          [&](Value reader, Value exists, Value unused) {
                            b.ifThen(exists, [&] {
                              b.atomic(arith::AtomicRMWKind::maxs, fluxCode,
                                       levels, b.add(half, blockOf(reader)));
                            });
                            return unused;
                          });
            });
          });
        });
      };
      auto groupCodes = [&](Value base) {
        // With invariant_levels, limit_levels_C keeps the codes of every
        // block once they are complete, all in one launch: a group whose
        // first block has its code kept has nothing to compute (the kept
        // codes are read instead of half `parity`, which stays 0).
        if (component.getInvariantLevels()) {
          Value kept = b.load(
              levels, b.add(b.mul(b.index(kLevelCached), blocksOf(kernel)),
                            blockOf(base)));
          Value isKept = b.cmp(arith::CmpIPredicate::ne, kept, b.i64(0));
          if (target.limitsLevelsPerLane())
            b.ifThen(isKept,
                     [&] { target.forEachLane(b, kernel, base, startFinest); });
          b.ifThen(b.xorOne(isKept), [&] { computeCodes(base); });
          return;
        }
        computeCodes(base);
      };
      target.forEachGroup(b, kernel, [&](Value base) {
        // In a big step of one base step every block's sub-step is 1, to
        // which every code decodes (limit_levels_C caps them at m; a code
        // of 0 decodes to m): none is computed. Where something holds the
        // big step at 1 (every num_steps 1, or a bounding component's),
        // the num_steps of every item would otherwise cost as much as a
        // third evaluation per base step. The codes of the next big step
        // go to the other half, which limit_levels_C clears.
        Value unitStep = b.cmp(arith::CmpIPredicate::eq, size, b.i64(1));
        if (target.limitsLevelsPerLane())
          b.ifThen(unitStep,
                   [&] { target.forEachLane(b, kernel, base, startFinest); });
        b.ifThen(b.xorOne(unitStep), [&] { groupCodes(base); });
      });
      target.reduceIntoClock(b, kernel, request, arith::AtomicRMWKind::mins,
                             sub + kSubUnitRequest);
    });
    if (failed(endKernel(kernel, simplan::LaunchShape::items, launches)))
      return failure();
  }

  // The sub-steps of the big step (section kLevelSteps of `levels @C`)
  // from the codes levels_C left in half `parity`. Block g's sub-step is
  // the largest assignment with s_g <= its own decoded code and
  // s_g <= 2 s_h for every neighbour h (docs/Model.md, "Levels"), which is
  //   s_g = min over blocks h of decode(h) * 2^hops(g, h),
  // hops(g, h) = ceil(distance(g, h) / radius), the fewest neighbour steps
  // from g to h (around the range when it wraps). A block with
  // 2^hops >= m bounds nothing (every code decodes to at most m), so only
  // the blocks within radius * ceil(log2 max_steps) count: a window
  // minimum per block, which every block computes on its own, at once
  // where lanes run side by side, instead of sweeping to a fixpoint in one
  // thread. A CPU sweeps (limitInOnePass below), as the reference executor
  // does (runtime/src/Reference.cpp); all agree because the largest such
  // assignment is unique.
  int64_t hops = radius == 0 ? 0 : int64_t(llvm::Log2_64_Ceil(maxSteps));
  // A distributed rank reads the levels of the blocks its items, their
  // ghost items and its interfaces' readers lie in (and, for the
  // neighbourhood codes, those within `radius` of them); each is limited
  // by the codes within `hops * radius` blocks. Every rank gathers the
  // codes of those blocks only (reduce_max_levels), a block more on each
  // side for the blocks its block's ends cut.
  int64_t levelReach = 0;
  auto planComponent = cast<simplan::ComponentOp>(
      SymbolTable::lookupSymbolIn(plan, component.getSymNameAttr()));
  if (distributed) {
    int64_t window = std::max({distributedHalo, reach, fluxBelow, fluxAbove});
    levelReach = window + kLevelBlock * (hops * radius + radius + 2);
    planComponent.setLevelReachAttr(
        Builder(plan.getContext()).getI64IntegerAttr(levelReach));
  }
  // The kernels below keep the codes of an invariant_levels component
  // (limit_levels_C), which the plan says so that a distributed run gathers
  // them once.
  planComponent.setKeepsLevels(component.getInvariantLevels());
  auto toI64 = [&](Value index) {
    return arith::IndexCastOp::create(b, b.loc, b.getI64Type(), index)
        .getResult();
  };
  auto stepsOf = [&](Kernel &kernel) {
    return b.mul(b.index(kLevelSteps), blocksOf(kernel));
  };
  // The blocks whose levels limit_levels_C limits: on one process every
  // block; on a rank those with items within the level reach of its own,
  // around the range, as the runtime's levelBlocksFor takes them. The
  // codes the runtime gathers lie there (and levels_C writes no others),
  // and the levels the rank's kernels read depend on no others; blocks
  // further away keep the code 0 and levels nothing reads, so the work
  // grows with the rank's block, not with the range. Two runs of blocks,
  // [first[k], first[k] + count[k]) (index values), that share none.
  struct BlockWindow {
    Value first[2], count[2];
  };
  auto orI = [&](Value x, Value y) {
    return arith::OrIOp::create(b, b.loc, x, y).getResult();
  };
  auto windowOf = [&](Kernel &kernel) -> BlockWindow {
    Value blocks = blocksOf(kernel);
    if (!distributed || !kernel.values.first)
      return {{b.index(0), b.index(0)}, {blocks, b.index(0)}};
    // In i64 items: the window may start below 0 or end past the range.
    Value zero = b.i64(0), range = toI64(kernel.values.range);
    Value first = toI64(kernel.values.first);
    Value own =
        b.sub(toI64(kernel.values.extent), b.i64(2 * kernel.values.halo));
    Value low = b.sub(first, b.i64(levelReach));
    Value high = b.add(b.add(first, own), b.i64(levelReach));
    // Within two blocks of the whole range it is the whole range, so that
    // the two runs never share a block.
    Value whole = b.cmp(arith::CmpIPredicate::sge,
                        b.add(b.sub(high, low), b.i64(2 * kLevelBlock)), range);
    Value below = b.cmp(arith::CmpIPredicate::slt, low, zero);
    Value above = b.cmp(arith::CmpIPredicate::sgt, high, range);
    // [0, high) and [low + range, range) when it starts below 0, [0, high -
    // range) and [low, range) when it ends past the range, else [low,
    // high) alone.
    Value aLow = b.select(orI(below, above), zero, low);
    Value aHigh = b.select(above, b.sub(high, range), high);
    Value bLow = b.select(below, b.add(low, range), b.select(above, low, zero));
    Value bHigh = b.select(orI(below, above), range, zero);
    aLow = b.select(whole, zero, aLow);
    aHigh = b.select(whole, range, aHigh);
    bLow = b.select(whole, zero, bLow);
    bHigh = b.select(whole, zero, bHigh);
    BlockWindow window;
    int k = 0;
    for (auto [from, to] : {std::pair(aLow, aHigh), std::pair(bLow, bHigh)}) {
      Value firstBlock = blockOf(b.toIndex(from));
      Value lastBlock =
          blockOf(b.toIndex(b.sub(b.max(to, b.i64(1)), b.i64(1))));
      Value count = b.add(b.sub(lastBlock, firstBlock), b.index(1));
      window.first[k] = firstBlock;
      window.count[k] = b.select(b.cmp(arith::CmpIPredicate::sgt, to, from),
                                 count, b.index(0));
      ++k;
    }
    return window;
  };
  // Block `w` of `window` (index), as an i64 block of the range.
  auto windowBlock = [&](const BlockWindow &window, Value w) {
    Value inFirst = b.cmp(arith::CmpIPredicate::ult, w, window.count[0]);
    return toI64(b.select(inFirst, b.add(window.first[0], w),
                          b.add(window.first[1], b.sub(w, window.count[0]))));
  };
  // Whether block `h` (i64) lies in `window`.
  auto inWindow = [&](const BlockWindow &window, Value h) {
    Value inside = b.constant(b.getI1Type(), 0);
    for (int k = 0; k < 2; ++k)
      inside = orI(inside, b.cmp(arith::CmpIPredicate::ult,
                                 b.sub(h, toI64(window.first[k])),
                                 toI64(window.count[k])));
    return inside;
  };
  // The block `distance` blocks below (or above) block g (i64 values) and
  // whether it is one: around the range when a buffer the component writes
  // wraps, else clamped into it. A distance is below the blocks
  // (minOverNeighbours stops there), so going around takes one addition or
  // subtraction of the blocks, not a remainder (an integer division per
  // neighbour and sweep).
  auto neighbourOf = [&](Value g, Value distance, bool below,
                         Value blocks) -> std::pair<Value, Value> {
    Value zero = b.i64(0), one = b.i64(1);
    Value h = below ? b.sub(g, distance) : b.add(g, distance);
    if (cyclic) {
      Value around = below
                         ? b.select(b.cmp(arith::CmpIPredicate::slt, h, zero),
                                    b.add(h, blocks), h)
                         : b.select(b.cmp(arith::CmpIPredicate::sge, h, blocks),
                                    b.sub(h, blocks), h);
      return {around, b.constant(b.getI1Type(), 1)};
    }
    Value valid = arith::AndIOp::create(
        b, b.loc, b.cmp(arith::CmpIPredicate::sge, h, zero),
        b.cmp(arith::CmpIPredicate::slt, h, blocks));
    return {b.min(b.max(h, zero), b.sub(blocks, one)), valid};
  };
  // The minimum of `initial` and `valueOf(h)` over the blocks h
  // `distance` blocks below and above block g (on the `sides` given: true
  // for below), for distance in [first, end) (an scf.for; blocks past a
  // range end that does not wrap count not).
  // Distances of `blocks` or more reach no block (or, around the range, one
  // already reached at a shorter distance, which bounds more): the loop
  // stops there, so a window far wider than the range costs the range.
  auto minOverNeighbours = [&](Value g, Value first, Value end, Value initial,
                               Value blocks,
                               function_ref<Value(Value h)> valueOf,
                               ArrayRef<bool> sides = {true, false}) -> Value {
    auto loop = scf::ForOp::create(b, b.loc, first, b.min(end, blocks),
                                   b.i64(1), ValueRange{initial});
    OpBuilder::InsertionGuard guard(b);
    b.setInsertionPointToStart(loop.getBody());
    Value distance = loop.getInductionVar();
    Value bound = loop.getRegionIterArg(0);
    for (bool below : sides) {
      auto [h, valid] = neighbourOf(g, distance, below, blocks);
      bound = b.select(valid, b.min(bound, valueOf(h)), bound);
    }
    scf::YieldOp::create(b, b.loc, bound);
    return loop.getResult(0);
  };
  // Block h's own power of two, from the code levels_C left in half
  // `parity` (i64 values). A code of 0 (a block no item of this process
  // wrote: another rank's, when the host did not all-reduce the codes
  // because the big step is 1) decodes to the big step, which every code
  // is within.
  // With invariant_levels, a block's code kept in section kLevelCached
  // (when not 0) stands for the one in half `parity`, which levels_C no
  // longer writes.
  bool keepsCodes = component.getInvariantLevels();
  auto keptAt = [&](Kernel &kernel, Value h) {
    return b.toIndex(
        b.add(b.mul(b.i64(kLevelCached), toI64(blocksOf(kernel))), h));
  };
  auto codeOf = [&](Kernel &kernel, Value levels, Value parity, Value h) {
    Value codes = b.mul(parity, toI64(blocksOf(kernel)));
    Value code = b.load(levels, b.toIndex(b.add(codes, h)));
    if (!keepsCodes)
      return code;
    Value kept = b.load(levels, keptAt(kernel, h));
    return b.select(b.cmp(arith::CmpIPredicate::ne, kept, b.i64(0)), kept,
                    code);
  };
  // The unit `u` of the big step being limited (limit_levels_C sets it
  // before any of the functions below runs): the smallest num_steps of the
  // component's items (and its flux writer's interfaces), capped at m.
  Value limitUnit;
  // A block's sub-step is a power of two of units: the whole big step `m`
  // (counted as `whole`, the smallest power of two not below m / u) when
  // its minimum is `m` or more, else the largest power of two within its
  // minimum over the unit, below m / u (the minimum is at least the unit).
  auto decodedLevel = [&](Kernel &kernel, Value levels, Value parity,
                          Value size, Value whole, Value h) {
    Value code = codeOf(kernel, levels, parity, h);
    Value smallest = b.sub(b.i64(kLevelCode), code);
    // (At least 1: every minimum is at least the unit, which is the
    // smallest of them, so this only guards a level of 0.)
    Value units =
        b.max(arith::DivUIOp::create(b, b.loc, smallest, limitUnit).getResult(),
              b.i64(1));
    return b.floorPowerOfTwo(b.select(
        b.cmp(arith::CmpIPredicate::sge, smallest, size), whole, units));
  };
  // Block g's sub-step into section kLevelSteps, and its code in half
  // 1 - parity, the previous big step's, cleared for the next (0 is the
  // identity of the codes). With invariant_levels, the block's code is
  // kept once the codes are complete: after a big step longer than one
  // base step, whose codes a distributed run all-reduced (it shares none
  // for a big step of 1). Every block of the window is kept in the same
  // launch, so levels_C finds all or none of a group's blocks kept; the
  // value kept is the one every lane of this launch decodes (kept or in
  // half `parity`), whichever it reads.
  auto storeLevel = [&](Kernel &kernel, Value levels, Value parity, Value size,
                        Value g, Value level) {
    b.store(level, levels, b.add(stepsOf(kernel), b.toIndex(g)));
    Value other = b.mul(b.toIndex(b.xorOne(parity)), blocksOf(kernel));
    b.store(b.i64(0), levels, b.add(other, b.toIndex(g)));
    if (keepsCodes)
      b.ifThen(b.cmp(arith::CmpIPredicate::sgt, size, b.i64(1)), [&] {
        b.store(codeOf(kernel, levels, parity, g), levels, keptAt(kernel, g));
      });
  };
  auto limitedLevel = [&](Kernel &kernel, Value levels, Value parity,
                          Value size, Value whole, Value g) -> Value {
    Value one = b.i64(1);
    Value blocks = toI64(blocksOf(kernel));
    auto decode = [&](Value h) {
      return decodedLevel(kernel, levels, parity, size, whole, h);
    };
    Value level = decode(g);
    if (hops == 0)
      return level;
    auto outer = scf::ForOp::create(b, b.loc, one, b.i64(hops + 1), one,
                                    ValueRange{level});
    OpBuilder::InsertionGuard guard(b);
    b.setInsertionPointToStart(outer.getBody());
    Value d = outer.getInductionVar();
    Value nearest = b.add(b.mul(b.sub(d, one), b.i64(radius)), one);
    Value bound = minOverNeighbours(
        g, nearest, b.add(nearest, b.i64(radius)), outer.getRegionIterArg(0),
        blocks, [&](Value h) {
          return arith::ShLIOp::create(b, b.loc, decode(h), d).getResult();
        });
    scf::YieldOp::create(b, b.loc, bound);
    return outer.getResult(0);
  };
  // Block g's limited sub-step, stored (storeLevel) and returned.
  auto limitBlock = [&](Kernel &kernel, Value levels, Value parity, Value size,
                        Value whole, Value g) {
    Value level = limitedLevel(kernel, levels, parity, size, whole, g);
    storeLevel(kernel, levels, parity, size, g, level);
    return level;
  };
  // Runs `body(g)` (i64) for every block of the window (windowOf),
  // spread over the lanes of an items launch: lane k of its `count` lanes
  // takes the window's blocks k, k + count, ... On one process `count` is
  // the range, so every block has a lane of its own; a rank's launch
  // covers its own items, fewer than the window's blocks take only where
  // the level reach is wide.
  auto forEachBlockOfLanes = [&](Kernel &kernel,
                                 function_ref<void(Value)> body) {
    Value first = kernel.values.first ? kernel.values.first : b.index(0);
    Value count = kernel.values.first ? b.sub(kernel.values.extent,
                                              b.index(2 * kernel.values.halo))
                                      : kernel.values.range;
    BlockWindow window = windowOf(kernel);
    Value blocks = b.add(window.count[0], window.count[1]);
    auto blocksFrom = [&](Value lane) {
      auto loop = scf::ForOp::create(b, b.loc, lane, blocks, count);
      OpBuilder::InsertionGuard guard(b);
      b.setInsertionPoint(loop.getBody()->getTerminator());
      body(windowBlock(window, loop.getInductionVar()));
    };
    target.forEachGroup(b, kernel, [&](Value base) {
      // A group whose lanes all lie past the blocks has none to take.
      Value low = b.sub(base, first);
      b.ifThen(b.cmp(arith::CmpIPredicate::ult, low, blocks), [&] {
        if (target.splitsGroups()) {
          // One thread runs the group's lanes: a plain loop, not a lanes
          // loop to widen, since a lane's work is a whole block's. Lanes
          // from `blocks` on take none, and a group of 4096 lanes over 128
          // blocks would otherwise spend a loop trip on each of them in
          // every big step.
          Value high = b.min(
              b.min(b.add(low, target.groupSize(b, kernel)), count), blocks);
          auto lanes = scf::ForOp::create(b, b.loc, low, high, b.index(1));
          OpBuilder::InsertionGuard guard(b);
          b.setInsertionPoint(lanes.getBody()->getTerminator());
          blocksFrom(lanes.getInductionVar());
          return;
        }
        target.forEachLane(b, kernel, base, [&](const Lane &lane) {
          b.ifThen(lane.active, [&] { blocksFrom(b.sub(lane.item, first)); });
        });
      });
    });
  };

  // The neighbourhood codes of block g for the big step, so that a slot
  // kernel tells from one value per block whether the items a block's
  // items reach have its own sub-step (section kLevelStepCodes; and, for a
  // flux pair, whether its interfaces' readers do: kLevelFluxCodes), from
  // `levelAt(h)`, the sub-step of block h (i64).
  // (`whole`: the sub-step of the whole big step, that of an interface
  // nothing reads.)
  auto codesOfBlock = [&](Kernel &kernel, Value levels, Value whole, Value g,
                          function_ref<Value(Value)> levelAt) {
    Value one = b.i64(1), zero = b.i64(0);
    Value blocks = toI64(blocksOf(kernel));
    // The minimum of `init` and `valueAt(k)` for k in [from, to) (i64).
    auto minOver = [&](Value from, Value to, Value init,
                       function_ref<Value(Value)> valueAt) {
      auto loop = scf::ForOp::create(b, b.loc, from, to, one, ValueRange{init});
      OpBuilder::InsertionGuard guard(b);
      b.setInsertionPointToStart(loop.getBody());
      scf::YieldOp::create(
          b, b.loc,
          b.min(loop.getRegionIterArg(0), valueAt(loop.getInductionVar())));
      return loop.getResult(0);
    };
    Value range = toI64(kernel.values.range);
    Value blockItems = b.i64(kLevelBlock);
    // Whether the items a block's items reach (through each `window` of
    // offsets `lo, hi` from its first and last item and, unless `clipped`
    // to the range, all inside it) have its own sub-step: then the code is
    // that sub-step, else minus `mixed(g, first, last)`, the finest sub-step
    // an item of the block takes (a slot that is not a multiple of it
    // starts none of them).
    auto neighbourhoodCode =
        [&](int64_t section, ArrayRef<std::pair<int64_t, int64_t>> windows,
            bool clipped, function_ref<Value(Value, Value, Value)> mixed) {
          Value own = levelAt(g);
          Value firstItem = b.mul(g, blockItems);
          Value lastItem = b.min(b.add(firstItem, b.i64(kLevelBlock - 1)),
                                 b.sub(range, one));
          Value lastOfRange = b.sub(range, one);
          Value inStep = b.constant(b.getI1Type(), 1);
          for (auto [lo, hi] : windows) {
            Value low = b.add(firstItem, b.i64(lo));
            Value high = b.add(lastItem, b.i64(hi));
            if (!clipped)
              inStep = arith::AndIOp::create(
                  b, b.loc, inStep,
                  arith::AndIOp::create(
                      b, b.loc, b.cmp(arith::CmpIPredicate::sge, low, zero),
                      b.cmp(arith::CmpIPredicate::slt, high, range)));
            // Clamped into the range: a read past an end reads the end's
            // item (or, under zero, none; testing it too only costs time).
            auto clamp = [&](Value item) {
              return b.min(b.max(item, zero), lastOfRange);
            };
            Value lowBlock =
                arith::DivUIOp::create(b, b.loc, clamp(low), blockItems);
            Value highBlock =
                arith::DivUIOp::create(b, b.loc, clamp(high), blockItems);
            auto scan =
                scf::ForOp::create(b, b.loc, lowBlock, b.add(highBlock, one),
                                   one, ValueRange{inStep});
            {
              OpBuilder::InsertionGuard inner(b);
              b.setInsertionPointToStart(scan.getBody());
              Value same = b.cmp(arith::CmpIPredicate::eq,
                                 levelAt(scan.getInductionVar()), own);
              scf::YieldOp::create(b, b.loc,
                                   arith::AndIOp::create(
                                       b, b.loc, scan.getRegionIterArg(0), same)
                                       .getResult());
            }
            inStep = scan.getResult(0);
          }
          Value code =
              b.ifThenElse(
                   b.getI64Type(), inStep,
                   [&]() -> SmallVector<Value> { return {own}; },
                   [&]() -> SmallVector<Value> {
                     return {b.sub(zero, mixed(g, firstItem, lastItem))};
                   })
                  .getResult(0);
          b.store(code, levels,
                  b.toIndex(b.add(b.mul(b.i64(section), blocks), g)));
        };
    // Every item of a block of the component takes the block's sub-step.
    neighbourhoodCode(kLevelStepCodes, readWindows, /*clipped=*/!cyclic,
                      [&](Value g, Value, Value) { return levelAt(g); });
    if (!fluxWriter)
      return;
    // An interface takes the sub-step of its coarsest reader (the whole
    // big step when it has none), so a block next to a finer one is due
    // only at its own sub-steps, not at every sub-step of the finer block
    // its state reads reach. The interfaces whose readers all lie in the
    // block take its sub-step; the others (at most the window's width at
    // either end) are folded one by one.
    ArrayRef<int64_t> offsets = fluxWriter.getFluxWindowAttr().asArrayRef();
    auto interfaceLevel = [&](Value interface) {
      Value coarsest = foldReaders(
          kernel, b.toIndex(interface), zero,
          [&](Value reader, Value exists, Value coarsest) {
            Value block = toI64(
                arith::DivUIOp::create(b, b.loc, reader, b.index(kLevelBlock)));
            return b.select(exists, b.max(coarsest, levelAt(block)), coarsest);
          });
      return b.select(b.cmp(arith::CmpIPredicate::eq, coarsest, zero), whole,
                      coarsest);
    };
    auto finestInterface = [&](Value g, Value first, Value last) {
      // Interface j reads j - o, o in [offsets[0], offsets[1]]: all in the
      // block for j in [first + offsets[1], last + offsets[0]].
      Value end = b.add(last, one);
      Value innerLow = b.max(first, b.add(first, b.i64(offsets[1])));
      Value innerHigh = b.min(last, b.add(last, b.i64(offsets[0])));
      Value hasInner = b.cmp(arith::CmpIPredicate::sle, innerLow, innerHigh);
      Value finest = b.select(hasInner, levelAt(g), whole);
      Value lowEnd = b.min(innerLow, end);
      finest = minOver(first, lowEnd, finest, interfaceLevel);
      return minOver(b.max(b.add(innerHigh, one), lowEnd), end, finest,
                     interfaceLevel);
    };
    neighbourhoodCode(kLevelFluxCodes, {{-fluxBelow, fluxAbove}},
                      /*clipped=*/false, finestInterface);
  };

  // Block `g` in a big step of one base step: its sub-step is 1 whatever
  // its items ask, and its codes are those of every level 1 (no limit to
  // compute).
  auto unitBlock = [&](Kernel &kernel, Value levels, Value parity, Value size,
                       Value g) {
    Value one = b.i64(1);
    storeLevel(kernel, levels, parity, size, g, one);
    codesOfBlock(kernel, levels, size, g, [&](Value) { return one; });
  };

  // Where the run of equal codes of `codeSection` that holds each block
  // ends (the block after its last), from the last block back: what a
  // slot kernel walks where one thread runs a group's lanes (splitsGroups).
  // Each run of the window (windowOf) on its own: a run of codes ends
  // where the window's run does.
  auto runEnds = [&](Kernel &kernel, Value levels, int64_t codeSection,
                     int64_t runSection) {
    Value one = b.i64(1), zero = b.i64(0);
    Value blocks = toI64(blocksOf(kernel));
    auto elementOf = [&](int64_t section, Value block) {
      return b.toIndex(b.add(b.mul(b.i64(section), blocks), block));
    };
    BlockWindow window = windowOf(kernel);
    for (int k = 0; k < 2; ++k) {
      Value start = toI64(window.first[k]);
      Value stop = b.add(start, toI64(window.count[k]));
      auto loop =
          scf::ForOp::create(b, b.loc, zero, toI64(window.count[k]), one);
      OpBuilder::InsertionGuard guard(b);
      b.setInsertionPoint(loop.getBody()->getTerminator());
      Value g = b.sub(b.sub(stop, one), loop.getInductionVar());
      Value next = b.add(g, one);
      Value end =
          b.ifThenElse(
               b.getI64Type(), b.cmp(arith::CmpIPredicate::slt, next, stop),
               [&]() -> SmallVector<Value> {
                 Value same =
                     b.cmp(arith::CmpIPredicate::eq,
                           b.load(levels, elementOf(codeSection, next)),
                           b.load(levels, elementOf(codeSection, g)));
                 return {b.select(
                     same, b.load(levels, elementOf(runSection, next)), next)};
               },
               [&]() -> SmallVector<Value> { return {next}; })
              .getResult(0);
      b.store(end, levels, elementOf(runSection, g));
    }
  };

  // Where one thread runs a group's lanes (a CPU): the same sub-steps and
  // codes in one pass of one thread, which costs less than every lane's
  // window minima: each block's code decoded into its sub-step, then
  // forward and backward sweeps that lower a block to twice its finest
  // neighbour (one each way, or around a wrapping range until nothing
  // changes: below) (the levels only go down, each at most
  // log2(m) times, and the result is the largest assignment that meets the
  // rule, whatever the order: the window minimum above), the finest, the
  // codes and the ends of their runs.
  auto limitInOnePass = [&](Kernel &kernel, Value levels, Value parity,
                            Value size, Value whole) {
    Value one = b.i64(1), zero = b.i64(0);
    Value blocks = toI64(blocksOf(kernel));
    Value steps = toI64(stepsOf(kernel));
    // The window's blocks (windowOf), walked as 0 .. count - 1; a block
    // outside it bounds nothing (its level reads as the big step).
    BlockWindow window = windowOf(kernel);
    Value count = toI64(b.add(window.count[0], window.count[1]));
    auto blockAt = [&](Value w) { return windowBlock(window, b.toIndex(w)); };
    auto at = [&](Value block) { return b.toIndex(b.add(steps, block)); };
    auto levelAt = [&](Value block) {
      return b.select(inWindow(window, block), b.load(levels, at(block)),
                      whole);
    };
    // In a big step of one base step every block's sub-step is 1, which
    // needs no limit: every block's level and codes follow at once (the
    // codes as when every level reads 1), at a fraction of the sweeps'
    // cost. Where something holds the big step at 1 (a bounding
    // component's stiff item), the sweeps would otherwise cost about as
    // much as the slot itself.
    auto unitStep = b.ifThenElse(
        TypeRange{}, b.cmp(arith::CmpIPredicate::eq, size, one),
        [&]() -> SmallVector<Value> {
          auto blocksLoop = scf::ForOp::create(b, b.loc, zero, count, one);
          OpBuilder::InsertionGuard guard(b);
          b.setInsertionPoint(blocksLoop.getBody()->getTerminator());
          unitBlock(kernel, levels, parity, size,
                    blockAt(blocksLoop.getInductionVar()));
          return {};
        },
        [&]() -> SmallVector<Value> { return {}; });
    OpBuilder::InsertionGuard unitGuard(b);
    b.setInsertionPoint(unitStep.elseBlock()->getTerminator());
    {
      auto decode = scf::ForOp::create(b, b.loc, zero, count, one);
      OpBuilder::InsertionGuard guard(b);
      b.setInsertionPoint(decode.getBody()->getTerminator());
      Value k = blockAt(decode.getInductionVar());
      storeLevel(kernel, levels, parity, size, k,
                 decodedLevel(kernel, levels, parity, size, whole, k));
    }
    // Lowers block `g` to twice its finest neighbour on the side the
    // sweep comes from (`below` for a forward sweep); returns whether it
    // changed. The side ahead is the other sweep's: a forward sweep that
    // also looked ahead would read blocks not yet lowered, which bound
    // nothing the backward sweep does not, at twice the loads.
    auto relax = [&](Value g, bool below) -> Value {
      Value own = levelAt(g);
      Value bound = own;
      if (radius > 0)
        bound = minOverNeighbours(g, one, b.i64(radius + 1), own, blocks,
                                  [&](Value h) {
                                    return arith::ShLIOp::create(
                                               b, b.loc, levelAt(h), one)
                                        .getResult();
                                  },
                                  {below});
      b.store(bound, levels, at(g));
      return b.cmp(arith::CmpIPredicate::slt, bound, own);
    };
    // A forward and a backward sweep; whether they lowered a block.
    auto sweep = [&]() -> Value {
      Value changed = b.constant(b.getI1Type(), 0);
      for (bool forward : {true, false}) {
        auto pass =
            scf::ForOp::create(b, b.loc, zero, count, one, ValueRange{changed});
        OpBuilder::InsertionGuard inner(b);
        b.setInsertionPointToStart(pass.getBody());
        Value k = pass.getInductionVar();
        Value g = blockAt(forward ? k : b.sub(b.sub(count, one), k));
        Value any = arith::OrIOp::create(b, b.loc, pass.getRegionIterArg(0),
                                         relax(g, forward));
        scf::YieldOp::create(b, b.loc, any);
        b.setInsertionPointAfter(pass);
        changed = pass.getResult(0);
      }
      return changed;
    };
    // Without a wrap the blocks are walked in the order of the range, and
    // one sweep each way reaches the fixpoint: the forward sweep leaves
    // each block the minimum over the blocks before it of c_h * 2^hops,
    // the backward sweep adds those after it (a block lowered by a later
    // one stays within twice of it). Around a range the shortest way from
    // a block may wrap past the sweep's start: sweeps until none changes.
    if (!cyclic) {
      sweep();
    } else {
      auto sweeps = scf::WhileOp::create(
          b, b.loc, b.getI1Type(), ValueRange{b.constant(b.getI1Type(), 1)});
      OpBuilder::InsertionGuard guard(b);
      Block *before =
          b.createBlock(&sweeps.getBefore(), {}, b.getI1Type(), b.loc);
      scf::ConditionOp::create(b, b.loc, before->getArgument(0),
                               before->getArguments());
      b.createBlock(&sweeps.getAfter(), {}, b.getI1Type(), b.loc);
      scf::YieldOp::create(b, b.loc, sweep());
    }
    auto finest =
        scf::ForOp::create(b, b.loc, zero, count, one, ValueRange{whole});
    {
      OpBuilder::InsertionGuard guard(b);
      b.setInsertionPointToStart(finest.getBody());
      Value g = blockAt(finest.getInductionVar());
      codesOfBlock(kernel, levels, whole, g, levelAt);
      scf::YieldOp::create(b, b.loc,
                           b.min(finest.getRegionIterArg(0), levelAt(g)));
    }
    b.store(finest.getResult(0), kernel.clock, b.index(sub + kSubSize));
    b.setInsertionPoint(unitStep.thenBlock()->getTerminator());
    b.store(one, kernel.clock, b.index(sub + kSubSize));
    b.setInsertionPointAfter(unitStep);
    runEnds(kernel, levels, kLevelStepCodes, kLevelStepRuns);
    if (fluxWriter)
      runEnds(kernel, levels, kLevelFluxCodes, kLevelFluxRuns);
  };
  // Levels that depend on the state often stay as they were from one big
  // step to the next (a stiff region that moves slowly, or none), and what
  // limitInOnePass computes depends on the codes in half `parity` and m
  // alone. So it keeps the codes it limited, plus 1, in section
  // kLevelCached (which only an invariant_levels component uses otherwise)
  // and m in the sub-step clock's Estimate slot (which only a grid_sync
  // component uses otherwise; `advance` leaves it), and where neither
  // changed, the sub-steps, codes and runs in `levels` still hold: one pass
  // compares the codes, clears half 1 - parity for the next big step, as
  // storeLevel does, and takes the finest sub-step again. Zeroed levels (a
  // run from the initial state, a restart) match no code plus 1, whatever
  // the clock says.
  auto limitUnlessUnchanged = [&](Kernel &kernel, Value levels, Value parity,
                                  Value size, Value whole) {
    Value zero = b.i64(0), one = b.i64(1);
    Value blocks = toI64(blocksOf(kernel));
    Value codes = b.mul(parity, blocks);
    Value cleared = b.mul(b.xorOne(parity), blocks);
    Value cached = b.mul(b.i64(kLevelCached), blocks);
    Value steps = toI64(stepsOf(kernel));
    BlockWindow window = windowOf(kernel);
    Value count = toI64(b.add(window.count[0], window.count[1]));
    Value limitedFor = b.index(sub + kSubEstimate);
    auto compare =
        scf::ForOp::create(b, b.loc, zero, count, one,
                           ValueRange{b.constant(b.getI1Type(), 1), whole});
    {
      OpBuilder::InsertionGuard guard(b);
      b.setInsertionPointToStart(compare.getBody());
      Value g = windowBlock(window, b.toIndex(compare.getInductionVar()));
      auto at = [&](Value section) { return b.toIndex(b.add(section, g)); };
      Value same =
          b.cmp(arith::CmpIPredicate::eq, b.add(b.load(levels, at(codes)), one),
                b.load(levels, at(cached)));
      b.store(zero, levels, at(cleared));
      scf::YieldOp::create(
          b, b.loc,
          ValueRange{
              arith::AndIOp::create(b, b.loc, compare.getRegionIterArg(0), same)
                  .getResult(),
              b.min(compare.getRegionIterArg(1), b.load(levels, at(steps)))});
    }
    // The levels depend on m and the unit (which other blocks' items, or a
    // flux writer's interfaces that no block reads, may set): both, as
    // one key (u <= m <= max_steps).
    Value key = b.add(b.mul(limitUnit, b.i64(maxSteps + 1)), size);
    Value unchanged = arith::AndIOp::create(
        b, b.loc, compare.getResult(0),
        b.cmp(arith::CmpIPredicate::eq, b.load(kernel.clock, limitedFor), key));
    b.ifThenElse(
        TypeRange{}, unchanged,
        [&]() -> SmallVector<Value> {
          b.store(compare.getResult(1), kernel.clock, b.index(sub + kSubSize));
          return {};
        },
        [&]() -> SmallVector<Value> {
          limitInOnePass(kernel, levels, parity, size, whole);
          auto keep = scf::ForOp::create(b, b.loc, zero, count, one);
          OpBuilder::InsertionGuard guard(b);
          b.setInsertionPoint(keep.getBody()->getTerminator());
          Value g = windowBlock(window, b.toIndex(keep.getInductionVar()));
          b.store(b.add(b.load(levels, b.toIndex(b.add(codes, g))), one),
                  levels, b.toIndex(b.add(cached, g)));
          b.setInsertionPointAfter(keep);
          b.store(key, kernel.clock, limitedFor);
          return {};
        });
  };
  // With invariant_levels, what limitInOnePass computes (every block's
  // sub-step, the codes, their runs and the finest) depends on the kept
  // codes and m alone, so once the codes are kept it is computed again only
  // when m changes (the end of the run, a bounding component's estimate).
  // The two code halves are no longer read or written then (levels_C
  // writes no codes, and a distributed run gathers none), so block g's
  // entries there hold the m of the last computation (half 0) and its
  // finest sub-step (half 1); a code left there is above any m.
  auto limitUnlessKept = [&](Kernel &kernel, Value levels, Value parity,
                             Value size, Value whole, Value g) {
    if (!keepsCodes) {
      limitUnlessUnchanged(kernel, levels, parity, size, whole);
      return;
    }
    Value limitedAt = b.toIndex(g);
    Value finestAt = b.toIndex(b.add(toI64(blocksOf(kernel)), g));
    auto isKept = [&] {
      return b.cmp(arith::CmpIPredicate::ne, b.load(levels, keptAt(kernel, g)),
                   b.i64(0));
    };
    Value same = arith::AndIOp::create(
        b, b.loc, isKept(),
        b.cmp(arith::CmpIPredicate::eq, b.load(levels, limitedAt), size));
    auto branch = scf::IfOp::create(b, b.loc, TypeRange{}, same,
                                    /*withElseRegion=*/true);
    OpBuilder::InsertionGuard guard(b);
    b.setInsertionPointToStart(branch.thenBlock());
    b.store(b.load(levels, finestAt), kernel.clock, b.index(sub + kSubSize));
    b.setInsertionPointToStart(branch.elseBlock());
    limitInOnePass(kernel, levels, parity, size, whole);
    b.ifThen(isKept(), [&] {
      b.store(size, levels, limitedAt);
      b.store(b.load(kernel.clock, b.index(sub + kSubSize)), levels, finestAt);
    });
  };

  // limit_levels_C: every block's sub-step, no more than twice as coarse
  // as a neighbour; the finest of them (the sub-step clock's Size: the
  // distance between slots where some block starts one); and each block's
  // neighbourhood codes. Where lanes run side by side (a GPU) one lane per
  // block, the finest by an atomic minimum from m (which levels_C set) and
  // the codes from the neighbours' sub-steps, which the lane computes again
  // (a few window minima) rather than wait for their lanes in a launch of
  // its own. Else one pass by one lane, which also finds where each run of
  // equal codes ends (limitInOnePass).
  {
    Kernel kernel = beginKernel(getKernelName(kernels, "limit_levels", name));
    Value begin, size, parity;
    readClock(kernel, begin, size, parity);
    Value levels = kernel.levels.lookup(symbol);
    Value running = b.cmp(arith::CmpIPredicate::sgt, size, b.i64(0));
    // The unit: the smallest num_steps levels_C found (on every rank: the
    // runtime's reduction of the levels), capped at m; 0 (none found: every
    // block's codes are kept, or the big step is 1) stands for m.
    Value requested = b.add(
        b.load(kernel.clock, b.index(sub + kSubUnitRequest)), b.i64(kUnitBias));
    limitUnit = b.max(b.min(requested, size), b.i64(1));
    Value whole = wholeStepOf(unitsOf(size, limitUnit));
    // The lane of the window's first block records it for the slots.
    auto recordUnit = [&](Kernel &kernel, Value g) {
      Value firstBlock = toI64(windowOf(kernel).first[0]);
      b.ifThen(b.cmp(arith::CmpIPredicate::eq, g, firstBlock), [&] {
        b.store(limitUnit, kernel.clock, b.index(sub + kSubUnit));
      });
    };
    if (target.limitsLevelsPerLane()) {
      b.ifThen(running, [&] {
        // A big step of one base step: every sub-step is 1 (as in
        // limitInOnePass), and the finest is m, which levels_C set.
        Value one = b.i64(1);
        Value unitStep = b.cmp(arith::CmpIPredicate::eq, size, one);
        forEachBlockOfLanes(kernel, [&](Value g) {
          recordUnit(kernel, g);
          b.ifThenElse(
              TypeRange{}, unitStep,
              [&]() -> SmallVector<Value> {
                unitBlock(kernel, levels, parity, size, g);
                return {};
              },
              [&]() -> SmallVector<Value> {
                Value level =
                    limitBlock(kernel, levels, parity, size, whole, g);
                b.atomic(arith::AtomicRMWKind::mins, level, kernel.clock,
                         b.index(sub + kSubSize));
                codesOfBlock(kernel, levels, whole, g, [&](Value h) {
                  return b.select(
                      b.cmp(arith::CmpIPredicate::eq, h, g), level,
                      limitedLevel(kernel, levels, parity, size, whole, h));
                });
                return {};
              });
        });
      });
      if (target.splitsGroups())
        b.ifThen(running, [&] {
          target.afterLastInvocation(b, kernel, sub + kSubCount, [&] {
            runEnds(kernel, levels, kLevelStepCodes, kLevelStepRuns);
            if (fluxWriter)
              runEnds(kernel, levels, kLevelFluxCodes, kLevelFluxRuns);
          });
        });
    } else {
      // The lane of the window's first block takes every block of the
      // window (a launch with the same arguments as the GPU's: the plan is
      // one for both).
      b.ifThen(running, [&] {
        Value firstBlock = toI64(windowOf(kernel).first[0]);
        forEachBlockOfLanes(kernel, [&](Value g) {
          b.ifThen(b.cmp(arith::CmpIPredicate::eq, g, firstBlock), [&] {
            b.store(limitUnit, kernel.clock, b.index(sub + kSubUnit));
            limitUnlessKept(kernel, levels, parity, size, whole, g);
          });
        });
      });
    }
    // Distributed plans: every rank limits the levels of the blocks within
    // its level reach, from the codes of the ranks' items there: their
    // maximum, as levels_C's atomics take it on one process.
    // (The runtime's reduction of the levels also takes the minimum of
    // the ranks' unit requests: Session::reduceUnitRequests.)
    if (distributed)
      pendingReduceLevels.push_back(FlatSymbolRefAttr::get(symbol));
    if (failed(endKernel(kernel, simplan::LaunchShape::items, launches)))
      return failure();
  }

  auto slots = simplan::RepeatOp::create(launches, b.loc,
                                         launches.getI64IntegerAttr(maxSteps));
  slots.getBody().emplaceBlock();
  OpBuilder slotLaunches = OpBuilder::atBlockEnd(&slots.getBody().front());

  // local_flux_E: the interfaces whose coarsest reading block starts a
  // sub-step at slot q, from C's state at T + q (its time levels), into
  // the target half, where C's reads find them until the next evaluation.
  if (fluxWriter) {
    StringRef fluxName = fluxWriter.getSymName();
    auto fluxWrites =
        llvm::to_vector(fluxWriter.getWrites().getAsRange<FlatSymbolRefAttr>());
    Kernel kernel = beginKernel(getKernelName(kernels, "local_flux", fluxName));
    // Only the interfaces due at the slot are evaluated.
    kernel.unevenGroups = true;
    LaneVar count = target.createLaneVar(b, kernel, b.getI32Type(), b.i32(0));
    Slot state = readSlot(kernel);
    Value size = state.size, parity = state.parity, levels = state.levels,
          slot = state.slot;
    b.ifThen(state.running, [&] {
      Value half = stepsOf(kernel);
      Value whole = wholeStepOf(state.units);
      // One evaluation of interface `lane.item` over `level` from T +
      // slot; reads the reader's state from its time levels, or (`uniform`:
      // every block it reaches at `level`, all in step) from the half
      // `readParity`.
      auto evaluateLane = [&](const Lane &lane, Value level, bool uniform,
                              Value readParity, bool counted = true) {
        KernelValues values = kernel.values;
        values.item = lane.item;
        if (uniform) {
          values.localParity = readParity;
          values.localBase = b.mul(b.toIndex(readParity), values.extent);
        } else {
          values.levels = levels;
          values.levelSlot = slot;
          values.levelEnd = size;
          values.levelUnit = state.unit;
          values.levelBase = half;
          values.levelsAtItem = true;
          values.levelsFromBothHalves = target.readsLevelsFromBothHalves();
        }
        // Its own state, read at its own item: every item is evaluated at
        // slot 0, from the value at T, and writes the target half, which
        // holds its latest value from then on.
        Value first = b.cmp(arith::CmpIPredicate::eq, slot, b.i64(0));
        for (FlatSymbolRefAttr write : fluxWrites)
          values.latestOwn.insert(write.getAttr());
        values.latestParity =
            b.select(first, values.sourceParity, values.targetParity);
        values.latestBase =
            b.select(first, values.sourceBase, values.targetBase);
        SmallVector<Value> results =
            evaluateSubStep(fluxWriter, state, lane, level, values);
        storeResults(kernel, lane, fluxWrites, results, values.targetBase,
                     values.targetParity, counted ? &count : nullptr);
      };
      // A part whose interfaces reach only blocks of one sub-step, all
      // inside the range (so every interface has its readers; its flux
      // codes say so): at a slot where they start, every interface steps
      // with them and reads them in step; at any other slot nothing is due.
      forEachPartAtSlot(
          kernel, levels, kLevelFluxCodes, kLevelFluxRuns, slot, parity,
          evaluationSlots.lookup(fluxWriter),
          [&](const Lane &lane, Value level, Value readParity, bool counted) {
            evaluateLane(lane, level, true, readParity, counted);
          },
          [&](const Lane &lane) {
            // The interface's sub-step: its coarsest reader's (the whole
            // big step when nothing reads it).
            Value coarsest = foldReaders(
                kernel, lane.item, b.i64(0),
                [&](Value reader, Value exists, Value coarsest) {
                  Value level = b.load(levels, b.add(half, blockOf(reader)));
                  return b.select(exists, b.max(coarsest, level), coarsest);
                });
            Value level =
                b.select(b.cmp(arith::CmpIPredicate::eq, coarsest, b.i64(0)),
                         whole, coarsest);
            b.ifThen(startsAt(slot, level),
                     [&] { evaluateLane(lane, level, false, Value()); });
          },
          nullptr, fluxBelow, fluxAbove);
      target.reduceIntoClock(b, kernel, count, arith::AtomicRMWKind::addi,
                             evaluationSlots.lookup(fluxWriter));
    });
    // It writes the target half, and only the interfaces due at the slot.
    // Interface j is due where its coarsest reader starts a sub-step; when
    // the readers' window holds offset 0, item j is one of them, and its
    // block's sub-step divides the coarsest one (powers of two): the
    // interfaces of the blocks that start a sub-step at the slot are a
    // superset of those due, and only they travel. Otherwise the whole
    // target half does.
    ArrayRef<int64_t> readers = fluxWriter.getFluxWindowAttr().asArrayRef();
    pendingWrittenHalf = readers[0] <= 0 && readers[1] >= 0
                             ? WrittenHalf::LocalFlux
                             : WrittenHalf::Target;
    if (failed(endKernel(kernel, simplan::LaunchShape::items, slotLaunches,
                         fluxWriter)))
      return failure();
  }

  // local_step_C: the items whose block's sub-step starts at slot q.
  {
    Kernel kernel = beginKernel(getKernelName(kernels, "local_step", name));
    // Only the blocks whose sub-step starts at the slot are evaluated.
    kernel.unevenGroups = true;
    // Evaluations counted per lane where a part is the whole group; a run
    // (splitsGroups) counts its lanes at once.
    std::optional<LaneVar> count;
    if (!target.splitsGroups())
      count = target.createLaneVar(b, kernel, b.getI32Type(), b.i32(0));
    Slot state = readSlot(kernel);
    Value size = state.size, parity = state.parity, levels = state.levels,
          now = state.now, slot = state.slot;
    b.ifThen(state.running, [&] {
      Value half = stepsOf(kernel);
      // One evaluation of a lane's item from T + slot over `level` base
      // steps, reading its own buffers at `readParity`, and through
      // `levels` at other items unless the group's neighbourhood is
      // uniform (`uniform`: every block its window reaches has `level`).
      auto evaluateLane = [&](const Lane &lane, Value level, Value readParity,
                              bool uniform, bool counted = true) {
        Value writeParity = b.xorOne(readParity);
        Value writeBase = b.mul(b.toIndex(writeParity), kernel.values.extent);
        KernelValues values = kernel.values;
        values.item = lane.item;
        values.localParity = readParity;
        values.localBase = b.mul(b.toIndex(readParity), values.extent);
        if (!uniform) {
          values.levels = levels;
          values.levelSlot = slot;
          values.levelEnd = size;
          values.levelUnit = state.unit;
          values.levelBase = half;
          values.levelsFromBothHalves = target.readsLevelsFromBothHalves();
        }
        SmallVector<Value> results =
            evaluateSubStep(component, state, lane, level, values);
        assert((!counted || count) && "a run counts its lanes at once");
        storeResults(kernel, lane, writes, results, writeBase, writeParity,
                     counted ? &*count : nullptr);
      };
      // A part whose window reaches blocks of one sub-step only (its step
      // codes say so): every lane reads its neighbours in step from one
      // half, as a grid-wide sub-step does (no level lookups; on a CPU, wide
      // loads). A window that wraps around the range takes the general
      // path, and a part whose blocks do not start at the slot none.
      forEachPartAtSlot(
          kernel, levels, kLevelStepCodes, kLevelStepRuns, slot, parity,
          evaluationSlots.lookup(component),
          [&](const Lane &lane, Value level, Value readParity, bool counted) {
            evaluateLane(lane, level, readParity, true, counted);
          },
          [&](const Lane &lane) {
            Value level = b.load(levels, b.add(half, blockOf(lane.item)));
            b.ifThen(startsAt(slot, level), [&] {
              evaluateLane(lane, level, readParityOf(parity, slot, level),
                           false);
            });
          },
          [&](const Lane &lane, Value level, Value readParity) {
            evaluateLane(lane, level, readParity, false, /*counted=*/false);
          });
      if (count)
        target.reduceIntoClock(b, kernel, *count, arith::AtomicRMWKind::addi,
                               evaluationSlots.lookup(component));
    });
    // The next slot where a block starts a sub-step, set by the invocation
    // that finishes the slot last (every other one has read `now`): no
    // launch of its own. The sub-step clock's count slot, which `lts` does
    // not otherwise use, counts the invocations. A slot past the big step
    // leaves the clock at T + m, so that its launch changes nothing at all
    // (a host that reads the clock may skip it: docs/Plan.md).
    b.ifThen(state.running, [&] {
      target.afterLastInvocation(b, kernel, sub + kSubCount, [&] {
        Value finest = b.load(kernel.clock, b.index(sub + kSubSize));
        b.store(b.min(b.add(now, b.mul(finest, state.unit)),
                      b.add(state.begin, size)),
                kernel.clock, b.index(sub + kSubBegin));
      });
    });
    pendingWrittenHalf = WrittenHalf::LocalStep;
    if (failed(endKernel(kernel, simplan::LaunchShape::items, slotLaunches,
                         component)))
      return failure();
  }

  // local_parity_C: after an even number of sub-steps a block's result is
  // in the source half.
  Kernel kernel = beginKernel(getKernelName(kernels, "local_parity", name));
  Value begin, size, parity;
  readClock(kernel, begin, size, parity);
  setHalves(kernel, parity, parity);
  Value levels = kernel.levels.lookup(symbol);
  b.ifThen(b.cmp(arith::CmpIPredicate::sgt, size, b.i64(0)), [&] {
    Value half = stepsOf(kernel);
    // The big step in units, M (ceil(m / u)).
    Value units = unitsOf(size, unitOf(kernel));
    // ceil(M / level) sub-steps, even when bit `level` (a power of two) of
    // M - 1 + level is clear: with M a power of two, unless level is M. A
    // part of one sub-step (its step codes are it or minus it) copies all
    // its items or none.
    auto even = [&](Value level) {
      return b.cmp(arith::CmpIPredicate::eq,
                   arith::AndIOp::create(
                       b, b.loc, b.add(b.sub(units, b.i64(1)), level), level),
                   b.i64(0));
    };
    forEachCodePart(
        kernel, levels, kLevelStepCodes, kLevelStepRuns,
        [&](Value code) { return even(b.max(code, b.sub(b.i64(0), code))); },
        [&](const Part &part, Value same, Value code, Value) {
          auto lanes = [&](function_ref<void(const Lane &)> body) {
            target.forEachLaneOf(b, kernel, part, [&](const Lane &lane) {
              b.ifThen(lane.active, [&] { body(lane); });
            });
          };
          auto branch = scf::IfOp::create(b, b.loc, TypeRange{}, same,
                                          /*withElseRegion=*/true);
          OpBuilder::InsertionGuard guard(b);
          b.setInsertionPointToStart(branch.thenBlock());
          Value level = b.max(code, b.sub(b.i64(0), code));
          b.ifThen(even(level), [&] {
            lanes([&](const Lane &lane) {
              copyToTarget(kernel, writes, lane.item);
            });
          });
          b.setInsertionPointToStart(branch.elseBlock());
          lanes([&](const Lane &lane) {
            Value level = b.load(levels, b.add(half, blockOf(lane.item)));
            b.ifThen(even(level),
                     [&] { copyToTarget(kernel, writes, lane.item); });
          });
        });
  });
  // The next big step's levels_C combines its unit request afresh, unless
  // the levels are kept (invariant_levels: levels_C stops combining, and
  // the request stays what it was); the last invocation clears it, when
  // every invocation has read the unit.
  if (!keepsCodes)
    b.ifThen(b.cmp(arith::CmpIPredicate::sgt, size, b.i64(0)), [&] {
      target.afterLastInvocation(b, kernel, sub + kSubCount, [&] {
        b.store(b.i64(0), kernel.clock, b.index(sub + kSubUnitRequest));
      });
    });
  // It writes the target half only; the source half travelled with the
  // slot that wrote it.
  pendingWrittenHalf = WrittenHalf::Target;
  return endKernel(kernel, simplan::LaunchShape::items, launches, component);
}
