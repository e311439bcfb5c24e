//===- KernelNames.cpp - kernel names from symbol names -------------------===//
//
// The one place a symbol name becomes part of a kernel name. Why the
// escaping looks as it does: a kernel name must be a C and PTX identifier
// (LLVM's NVPTX printer aborts on anything else), ordinary symbols should
// keep their names (`evaluate_C0`), and two symbols must not meet in one
// name (`@"a b"` and `@a_b`). Since every identifier is already some
// ordinary symbol's name, the escape sequence `__XX` is made unambiguous by
// escaping the one `_` that could start it: an `_` that is not followed by a
// letter, a digit or the end.
//
//===----------------------------------------------------------------------===//

#include "sim/Conversion/SimCommon/KernelNames.h"

#include "mlir/IR/SymbolTable.h"
#include "llvm/ADT/StringExtras.h"
#include "llvm/Support/xxhash.h"

using namespace mlir;
using namespace mlir::sim;

std::string mlir::sim::escapeKernelSymbol(StringRef symbol) {
  std::string escaped;
  escaped.reserve(symbol.size());
  for (size_t index = 0, size = symbol.size(); index < size; ++index) {
    unsigned char c = symbol[index];
    bool kept = llvm::isAlnum(c);
    if (c == '_')
      kept = index + 1 == size || llvm::isAlnum(symbol[index + 1]);
    if (kept) {
      escaped.push_back(c);
      continue;
    }
    escaped += "__";
    escaped.push_back(llvm::hexdigit(c >> 4, /*LowerCase=*/true));
    escaped.push_back(llvm::hexdigit(c & 15, /*LowerCase=*/true));
  }
  if (escaped.size() <= kMaxKernelSymbolChars)
    return escaped;
  // Cut, and keep the names of different symbols apart with a hash of the
  // whole name (stable across runs and hosts).
  std::string hash =
      llvm::utohexstr(llvm::xxh3_64bits(llvm::arrayRefFromStringRef(symbol)),
                      /*LowerCase=*/true, /*Width=*/16);
  escaped.resize(kMaxKernelSymbolChars - hash.size() - 1);
  return escaped + "_" + hash;
}

bool mlir::sim::isKernelIdentifier(StringRef name) {
  return !name.empty() && !llvm::isDigit(name.front()) &&
         llvm::all_of(name,
                      [](char c) { return llvm::isAlnum(c) || c == '_'; });
}

/// `name`, or `name` with the first suffix `_1`, `_2`, ... that no symbol of
/// `container` has.
static std::string makeUnique(Operation *container, std::string name) {
  auto taken = [&](StringRef candidate) {
    return container && SymbolTable::lookupSymbolIn(
                            container, StringAttr::get(container->getContext(),
                                                       candidate)) != nullptr;
  };
  if (!taken(name))
    return name;
  for (unsigned suffix = 1;; ++suffix) {
    std::string candidate = name + "_" + std::to_string(suffix);
    if (!taken(candidate))
      return candidate;
  }
}

std::string mlir::sim::getKernelName(Operation *container, StringRef family,
                                     StringRef symbol) {
  assert(isKernelIdentifier(family) && "a kernel family is an identifier");
  return makeUnique(container,
                    (family + "_" + escapeKernelSymbol(symbol)).str());
}

std::string mlir::sim::getKernelName(Operation *container, StringRef family) {
  assert(isKernelIdentifier(family) && "a kernel family is an identifier");
  return makeUnique(container, family.str());
}
