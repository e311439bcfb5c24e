//===- InitAllTranslations.h - register every sim translation ---*- C++ -*-===//
//
// One call that registers all of sim's translations, for sim-translate.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_INITALLTRANSLATIONS_H
#define SIM_INITALLTRANSLATIONS_H

#include "sim/Target/Bundle.h"
#include "sim/Target/PTX/TranslateToPTX.h"

namespace mlir::sim {

/// Registers every translation of sim with the global translation registry.
inline void registerSimTranslations() {
  static bool initOnce = [] {
    registerToPTXTranslations();
    registerToBundleTranslation();
    return true;
  }();
  (void)initOnce;
}

} // namespace mlir::sim

#endif // SIM_INITALLTRANSLATIONS_H
