//===- VectorAlignment.h - vectors whose elements are misaligned --*- C++
//-*-===//
//
// FlatBuffers reads scalars in place, so a vector of 8-byte elements must
// have its elements on an 8-byte boundary. The verifier of FlatBuffers 2.0
// (Debian 12's) checks a vector's length prefix (4 bytes) and its bounds,
// not the alignment of its elements (google/flatbuffers#8397): a damaged
// file passes it with an int64 vector 4 bytes off, and unpacking it loads a
// misaligned int64 (undefined behaviour; UBSan reports it, and the bundle
// fuzzer found it). The readers check every vector of 8-byte elements of
// their schemas after verifying a file and before unpacking it:
// RefComponent.local_window and .flux_window (Bundle.cpp) and
// Checkpoint.clock (Checkpoint.cpp). test/Fuzz/vector-alignment.test finds
// those vectors in runtime/schema/*.fbs and fails when one is not checked.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_VECTORALIGNMENT_H
#define SIM_RUNTIME_VECTORALIGNMENT_H

#include <flatbuffers/flatbuffers.h>

#include <cstdint>

namespace sim::rt {

/// Whether `vector` (null: absent) has its elements where their type's
/// alignment puts them. The buffer itself is aligned (the readers copy it
/// into a std::vector), so this is the offset the writer chose.
template <typename T>
bool elementsAligned(const flatbuffers::Vector<T> *vector) {
  return !vector ||
         reinterpret_cast<uintptr_t>(vector->Data()) % alignof(T) == 0;
}

} // namespace sim::rt

#endif // SIM_RUNTIME_VECTORALIGNMENT_H
