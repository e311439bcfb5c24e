//===- SharedObject.h - loading an ELF shared object from memory --*- C++
//-*-===//
//
// The CPU kernels (bundle section kind 4) and the reference functions
// (kind 6) are shared objects held in memory. dlopen needs a path: an
// anonymous memfd provides one without a file on disk.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_SHAREDOBJECT_H
#define SIM_RUNTIME_SHAREDOBJECT_H

#include <cstdint>
#include <string>
#include <vector>

namespace sim::rt {

/// Checks that `object` is a 64-bit little-endian ELF shared object whose
/// headers (the ELF header, the program and section header tables, every
/// segment's and section's bytes) lie inside it, before anything maps it;
/// throws SIM_ERROR_BUNDLE naming `what` ("the CPU kernels of ...").
void checkElfImage(const std::vector<uint8_t> &object, const std::string &what);

class SharedObject {
public:
  /// Checks that `object` is a 64-bit ELF shared object for this machine
  /// (checkElfImage, and its machine) and loads it; `what` (plural, "the
  /// CPU kernels of ...") names it in messages.
  SharedObject(const std::vector<uint8_t> &object, std::string what);
  ~SharedObject();
  SharedObject(const SharedObject &) = delete;
  SharedObject &operator=(const SharedObject &) = delete;

  /// The address of `name`, or null.
  void *find(const std::string &name) const;
  const std::string &what() const { return what_; }

private:
  std::string what_;
  void *library = nullptr;
  /// The memfd the library was loaded from, and the path it was loaded by.
  int memfd = -1;
  std::string path;
};

} // namespace sim::rt

#endif // SIM_RUNTIME_SHAREDOBJECT_H
