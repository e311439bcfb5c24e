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
#include <optional>
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
  // The segments. dlopen trusts them: a loadable segment dropped or grown
  // over the next one, or a dynamic table that points outside what is
  // mapped, crashes the dynamic loader itself. The CRC catches damage; this
  // catches a bundle whose objects were edited (or produced by something
  // else) and whose CRC was recomputed. The machine code itself cannot be
  // checked: a bundle carries native code, and running it trusts it.
  std::vector<Elf64_Phdr> loads;
  std::optional<Elf64_Phdr> dynamic;
  for (uint16_t i = 0; i < header.e_phnum; ++i) {
    Elf64_Phdr segment;
    std::memcpy(&segment,
                object.data() + header.e_phoff + uint64_t(i) * sizeof segment,
                sizeof segment);
    std::string name = "segment " + std::to_string(i);
    if (segment.p_offset > size || segment.p_filesz > size - segment.p_offset)
      bad(name + " (" + std::to_string(segment.p_filesz) + " bytes at offset " +
          std::to_string(segment.p_offset) + ") reaches past the end of its " +
          std::to_string(size) + " bytes");
    switch (segment.p_type) {
    case PT_NULL:
    case PT_NOTE:
    case PT_PHDR:
    case PT_GNU_EH_FRAME:
    case PT_GNU_STACK:
    case PT_GNU_RELRO:
    case PT_GNU_PROPERTY:
      break;
    case PT_LOAD:
      if (segment.p_filesz > segment.p_memsz)
        bad(name + " holds more bytes in the file than in memory");
      // At most 1 GiB in memory: the kernels' objects hold a few pages.
      if (segment.p_memsz > (uint64_t(1) << 30) ||
          segment.p_vaddr > (uint64_t(1) << 40))
        bad(name + " maps " + std::to_string(segment.p_memsz) +
            " bytes at address " + std::to_string(segment.p_vaddr));
      if (!loads.empty() &&
          loads.back().p_vaddr + loads.back().p_memsz > segment.p_vaddr)
        bad(name + " is loaded at " + std::to_string(segment.p_vaddr) +
            ", inside or before the loadable segment before it");
      loads.push_back(segment);
      break;
    case PT_DYNAMIC:
      if (dynamic)
        bad("two dynamic segments");
      dynamic = segment;
      break;
    default:
      bad(name + " has type " + std::to_string(segment.p_type) +
          ", which no shared object of sim-translate has (an interpreter, "
          "thread-local storage or an unknown type)");
    }
  }
  if (loads.empty())
    bad("no loadable segment");
  if (!dynamic)
    bad("no dynamic segment");
  // Where an address of the loaded object lies in the file, if it is
  // mapped from the file for `bytes` bytes.
  auto fileOffset = [&](uint64_t address,
                        uint64_t bytes) -> std::optional<uint64_t> {
    for (const Elf64_Phdr &load : loads)
      if (address >= load.p_vaddr && address - load.p_vaddr <= load.p_filesz &&
          bytes <= load.p_filesz - (address - load.p_vaddr))
        return load.p_offset + (address - load.p_vaddr);
    return std::nullopt;
  };
  auto mapped = [&](uint64_t address, uint64_t bytes, bool writable) {
    for (const Elf64_Phdr &load : loads)
      if (address >= load.p_vaddr && address - load.p_vaddr <= load.p_memsz &&
          bytes <= load.p_memsz - (address - load.p_vaddr))
        return !writable || (load.p_flags & PF_W);
    return false;
  };
  // The other segments describe parts of what is loaded (the dynamic
  // loader reads the program headers through PT_PHDR, protects PT_GNU_RELRO
  // and so on): each lies inside it, where its file bytes are.
  for (uint16_t i = 0; i < header.e_phnum; ++i) {
    Elf64_Phdr segment;
    std::memcpy(&segment,
                object.data() + header.e_phoff + uint64_t(i) * sizeof segment,
                sizeof segment);
    if (segment.p_type == PT_LOAD || segment.p_type == PT_NULL ||
        segment.p_type == PT_GNU_STACK)
      continue;
    std::optional<uint64_t> at = fileOffset(segment.p_vaddr, segment.p_filesz);
    if (!at || *at != segment.p_offset ||
        !mapped(segment.p_vaddr, segment.p_memsz, false))
      bad("segment " + std::to_string(i) + " (type " +
          std::to_string(segment.p_type) + ", " +
          std::to_string(segment.p_memsz) + " bytes at address " +
          std::to_string(segment.p_vaddr) +
          ") lies outside the loadable segments or elsewhere in the file");
    if (segment.p_type == PT_PHDR &&
        (segment.p_offset != header.e_phoff ||
         segment.p_filesz != uint64_t(header.e_phnum) * sizeof(Elf64_Phdr)))
      bad("segment " + std::to_string(i) +
          " does not describe the program header table");
  }
  std::optional<uint64_t> table =
      fileOffset(dynamic->p_vaddr, dynamic->p_filesz);
  if (!table || *table != dynamic->p_offset)
    bad("the dynamic segment lies outside the loadable segments");
  // Every address the dynamic table gives, and every place a relocation
  // writes to, lies in what is loaded.
  uint64_t relocations[2] = {0, 0}, relocationBytes[2] = {0, 0};
  for (uint64_t at = 0; at + sizeof(Elf64_Dyn) <= dynamic->p_filesz;
       at += sizeof(Elf64_Dyn)) {
    Elf64_Dyn entry;
    std::memcpy(&entry, object.data() + *table + at, sizeof entry);
    if (entry.d_tag == DT_NULL)
      break;
    switch (entry.d_tag) {
    case DT_HASH:
    case DT_GNU_HASH:
    case DT_STRTAB:
    case DT_SYMTAB:
    case DT_RELA:
    case DT_JMPREL:
    case DT_INIT_ARRAY:
    case DT_FINI_ARRAY:
    case DT_INIT:
    case DT_FINI:
    case DT_VERSYM:
    case DT_VERDEF:
    case DT_VERNEED:
    case DT_PLTGOT:
      if (!mapped(entry.d_un.d_ptr, 1, false))
        bad("its dynamic table gives address " +
            std::to_string(entry.d_un.d_ptr) + " (tag " +
            std::to_string(entry.d_tag) + "), which is not loaded");
      break;
    default:
      break;
    }
    if (entry.d_tag == DT_RELA)
      relocations[0] = entry.d_un.d_ptr;
    if (entry.d_tag == DT_RELASZ)
      relocationBytes[0] = entry.d_un.d_val;
    if (entry.d_tag == DT_JMPREL)
      relocations[1] = entry.d_un.d_ptr;
    if (entry.d_tag == DT_PLTRELSZ)
      relocationBytes[1] = entry.d_un.d_val;
  }
  for (int k = 0; k < 2; ++k) {
    if (!relocationBytes[k])
      continue;
    std::optional<uint64_t> from =
        fileOffset(relocations[k], relocationBytes[k]);
    if (!from)
      bad("its relocations (" + std::to_string(relocationBytes[k]) +
          " bytes at address " + std::to_string(relocations[k]) +
          ") are not in the file");
    for (uint64_t at = 0; at + sizeof(Elf64_Rela) <= relocationBytes[k];
         at += sizeof(Elf64_Rela)) {
      Elf64_Rela relocation;
      std::memcpy(&relocation, object.data() + *from + at, sizeof relocation);
      if (!mapped(relocation.r_offset, sizeof(uint64_t), true))
        bad("a relocation writes to address " +
            std::to_string(relocation.r_offset) +
            ", which is not in a writable loaded segment");
    }
  }
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
