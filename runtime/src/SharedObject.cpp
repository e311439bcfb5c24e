//===- SharedObject.cpp - loading an ELF shared object from memory --------===//
//
// The object is written to an anonymous memfd and dlopen'ed from
// /proc/self/fd, so nothing touches the file system; where memfd_create is
// missing, a temporary file is used and removed as soon as it is mapped.
//
//===----------------------------------------------------------------------===//

#include "SharedObject.h"
#include "Error.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <sys/mman.h>
#include <unistd.h>

namespace sim::rt {

namespace {

#if defined(__x86_64__)
constexpr uint16_t kHostMachine = 62; // EM_X86_64
constexpr const char *kHostName = "x86-64";
#elif defined(__aarch64__)
constexpr uint16_t kHostMachine = 183; // EM_AARCH64
constexpr const char *kHostName = "AArch64";
#else
constexpr uint16_t kHostMachine = 0;
constexpr const char *kHostName = "this machine";
#endif

void checkElf(const std::vector<uint8_t> &object, const std::string &what) {
  // The bundle reader checked the magic and a 64-byte header.
  // e_ident[EI_CLASS] == ELFCLASS64, e_type == ET_DYN, e_machine.
  uint16_t type = uint16_t(object[16] | object[17] << 8);
  uint16_t machine = uint16_t(object[18] | object[19] << 8);
  if (object[4] != 2 || type != 3)
    fail(SIM_ERROR_BUNDLE, what + " are not a 64-bit ELF shared object");
  if (kHostMachine && machine != kHostMachine)
    fail(SIM_ERROR_BUNDLE, what + " are for ELF machine " +
                               std::to_string(machine) + ", not for " +
                               kHostName);
}

} // namespace

SharedObject::SharedObject(const std::vector<uint8_t> &object,
                           std::string whatIn)
    : what_(std::move(whatIn)) {
  checkElf(object, what_);
  int fd = memfd_create("sim-shared-object", MFD_CLOEXEC);
  bool temporary = fd < 0;
  if (temporary) {
    const char *dir = std::getenv("TMPDIR");
    path = std::string(dir && *dir ? dir : "/tmp") + "/sim-kernels-XXXXXX";
    fd = mkstemp(path.data());
    if (fd < 0)
      fail(SIM_ERROR_BACKEND,
           "cannot create a file for " + what_ + ": " + std::strerror(errno));
  } else {
    path = "/proc/self/fd/" + std::to_string(fd);
  }
  auto cleanUp = [&] {
    close(fd);
    if (temporary)
      unlink(path.c_str());
  };
  size_t written = 0;
  while (written < object.size()) {
    ssize_t n = ::write(fd, object.data() + written, object.size() - written);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0) {
      int saved = errno;
      cleanUp();
      fail(SIM_ERROR_BACKEND,
           "cannot write " + what_ + ": " + std::strerror(saved));
    }
    written += size_t(n);
  }
  library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!library) {
    std::string error = dlerror();
    cleanUp();
    fail(SIM_ERROR_BACKEND, "cannot load " + what_ + ": " + error);
  }
  if (temporary)
    cleanUp();
  else
    memfd = fd;
}

SharedObject::~SharedObject() {
  dlclose(library);
  if (memfd < 0)
    return;
  // dlopen finds loaded objects by path first, and /proc/self/fd/N names
  // whatever file descriptor N is now: the descriptor is released only once
  // the object is really gone, so no later load can be mistaken for this
  // one.
  if (void *still = dlopen(path.c_str(), RTLD_NOW | RTLD_NOLOAD)) {
    dlclose(still);
    return;
  }
  close(memfd);
}

void *SharedObject::find(const std::string &name) const {
  return dlsym(library, name.c_str());
}

} // namespace sim::rt
