//===- KernelNames.h - kernel names from symbol names -----------*- C++ -*-===//
//
// Kernels are named after what they compute and for which symbol:
// `init_<buffer>`, `evaluate_<component>`, `total_<total>`, ... Symbol names
// may be any string (`@"B 4"`, `@"x.y"`, `@"Δx"`), but a kernel name ends
// up as a PTX `.entry` and, prefixed with `sim_cpu_`, as a C function that
// the runtime finds with dlsym, so it must be an identifier of both:
// letters, digits and `_`. Both the GPU and the CPU lowering name every
// kernel through this one function, so the two kernel sets of a bundle have
// the same names.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_CONVERSION_SIMCOMMON_KERNELNAMES_H
#define SIM_CONVERSION_SIMCOMMON_KERNELNAMES_H

#include "mlir/IR/Operation.h"
#include "llvm/ADT/StringRef.h"

#include <string>

namespace mlir::sim {

/// The longest escaped symbol part of a kernel name; a longer one is cut and
/// ends in a hash of the whole symbol name instead.
constexpr size_t kMaxKernelSymbolChars = 128;

/// Escapes `symbol` into letters, digits and `_`. Letters and digits stay;
/// `_` stays when a letter or digit or the end follows it; every other byte
/// (an `_` before anything else, and each byte of a non-ASCII character)
/// becomes `__` and two lowercase hex digits: `@"B 4"` is `B__204`,
/// `@"a_b"` stays `a_b`, `@"a__b"` is `a__5f_b`. The escaping is
/// one-to-one, so different symbols escape differently, except that an
/// escaped symbol longer than kMaxKernelSymbolChars is cut and ends in `_`
/// and 16 hex digits of a hash of `symbol`.
std::string escapeKernelSymbol(llvm::StringRef symbol);

/// The name of the kernel of `family` (an identifier such as `init` or
/// `substep_estimate`) for `symbol`: `<family>_<escaped symbol>`. Ordinary
/// symbols read as they are (`evaluate_C0`). When `container` (the symbol
/// table the kernel goes into) already holds the name, for instance
/// `substep_` + `@estimate_C` and `substep_estimate_` + `@C`, the name gets
/// the first free suffix `_1`, `_2`, ..., so every kernel of a container
/// has a name of its own.
std::string getKernelName(Operation *container, llvm::StringRef family,
                          llvm::StringRef symbol);
/// The name of a kernel that is not for a symbol (`advance`): `family`,
/// made unique in `container` as above.
std::string getKernelName(Operation *container, llvm::StringRef family);

/// Whether `name` is a kernel name: a non-empty string of ASCII letters,
/// digits and `_` that does not start with a digit (a C and PTX identifier).
bool isKernelIdentifier(llvm::StringRef name);

} // namespace mlir::sim

#endif // SIM_CONVERSION_SIMCOMMON_KERNELNAMES_H
