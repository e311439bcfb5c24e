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
#include <elf.h>
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

void checkMachine(const std::vector<uint8_t> &object, const std::string &what) {
  uint16_t machine = uint16_t(object[18] | object[19] << 8);
  if (kHostMachine && machine != kHostMachine)
    fail(SIM_ERROR_BUNDLE, what + " are for ELF machine " +
                               std::to_string(machine) + ", not for " +
                               kHostName);
}

} // namespace

void checkElfImage(const std::vector<uint8_t> &object,
                   const std::string &what) {
  auto bad = [&](const std::string &why) {
    fail(SIM_ERROR_BUNDLE, what + " are not a loadable shared object: " + why);
  };
  uint64_t size = object.size();
  if (size < sizeof(Elf64_Ehdr))
    bad("the " + std::to_string(size) + " bytes are too few for an ELF header");
  Elf64_Ehdr header;
  std::memcpy(&header, object.data(), sizeof header);
  if (std::memcmp(header.e_ident, ELFMAG, SELFMAG) != 0)
    bad("no ELF magic");
  if (header.e_ident[EI_CLASS] != ELFCLASS64 ||
      header.e_ident[EI_DATA] != ELFDATA2LSB ||
      header.e_ident[EI_VERSION] != EV_CURRENT)
    bad("not a 64-bit little-endian ELF file of the current version");
  if (header.e_type != ET_DYN)
    bad("an ELF file of type " + std::to_string(header.e_type) +
        ", not a shared object (" + std::to_string(ET_DYN) + ")");
  if (header.e_ehsize != sizeof(Elf64_Ehdr))
    bad("an ELF header of " + std::to_string(header.e_ehsize) + " bytes");
  // A table of `count` entries of `entry` bytes at `offset` inside the
  // object (64-bit arithmetic cannot overflow: every factor is below 2^32
  // or checked against the size first).
  auto checkTable = [&](uint64_t offset, uint64_t count, uint64_t entry,
                        uint64_t expected, const char *name) {
    if (count == 0)
      return;
    if (entry != expected)
      bad(std::string(name) + " entries of " + std::to_string(entry) +
          " bytes");
    if (offset > size || count * entry > size - offset)
      bad(std::string("the ") + name + " (" + std::to_string(count) +
          " entries at offset " + std::to_string(offset) +
          ") reaches past the end of its " + std::to_string(size) + " bytes");
  };
  checkTable(header.e_phoff, header.e_phnum, header.e_phentsize,
             sizeof(Elf64_Phdr), "program header table");
  checkTable(header.e_shoff, header.e_shnum, header.e_shentsize,
             sizeof(Elf64_Shdr), "section header table");
  if (header.e_phnum == 0)
    bad("no program headers: nothing to load");
  bool dynamic = false;
  for (uint16_t i = 0; i < header.e_phnum; ++i) {
    Elf64_Phdr segment;
    std::memcpy(&segment,
                object.data() + header.e_phoff + uint64_t(i) * sizeof segment,
                sizeof segment);
    if (segment.p_offset > size || segment.p_filesz > size - segment.p_offset)
      bad("segment " + std::to_string(i) + " (" +
          std::to_string(segment.p_filesz) + " bytes at offset " +
          std::to_string(segment.p_offset) + ") reaches past the end of its " +
          std::to_string(size) + " bytes");
    if (segment.p_type == PT_LOAD && segment.p_filesz > segment.p_memsz)
      bad("segment " + std::to_string(i) +
          " holds more bytes in the file than in memory");
    dynamic |= segment.p_type == PT_DYNAMIC;
  }
  if (!dynamic)
    bad("no dynamic segment");
  for (uint16_t i = 0; i < header.e_shnum; ++i) {
    Elf64_Shdr section;
    std::memcpy(&section,
                object.data() + header.e_shoff + uint64_t(i) * sizeof section,
                sizeof section);
    if (section.sh_type == SHT_NOBITS || section.sh_type == SHT_NULL)
      continue;
    if (section.sh_offset > size || section.sh_size > size - section.sh_offset)
      bad("section " + std::to_string(i) + " (" +
          std::to_string(section.sh_size) + " bytes at offset " +
          std::to_string(section.sh_offset) + ") reaches past the end of its " +
          std::to_string(size) + " bytes");
  }
}

SharedObject::SharedObject(const std::vector<uint8_t> &object,
                           std::string whatIn)
    : what_(std::move(whatIn)) {
  checkElfImage(object, what_);
  checkMachine(object, what_);
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
