//===- Output.cpp - the files sim-run writes ------------------------------===//

#include "Output.h"

#include "Options.h"
#include "Signals.h"

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <optional>
#include <set>
#include <sys/stat.h>
#include <unistd.h>

namespace simrun {

//===----------------------------------------------------------------------===//
// Names
//===----------------------------------------------------------------------===//

std::string sanitiseName(std::string_view name) {
  if (name.empty())
    return "_";
  static const char *hex = "0123456789ABCDEF";
  std::string stem;
  for (size_t i = 0; i < name.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(name[i]);
    bool kept = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') ||
                (c >= '0' && c <= '9') || c == '_' || c == '-' ||
                (c == '.' && i > 0);
    std::string piece = kept ? std::string(1, char(c))
                             : std::string{'%', hex[c >> 4], hex[c & 15]};
    if (stem.size() + piece.size() > kMaxStem)
      break;
    stem += piece;
  }
  return stem;
}

std::vector<std::string> dumpStems(const std::vector<std::string> &names) {
  std::set<std::string> taken;
  std::vector<std::string> stems;
  for (const std::string &name : names) {
    std::string base = sanitiseName(name);
    std::string stem = base;
    auto free = [&](const std::string &candidate) {
      for (const char *suffix : kDumpSuffixes)
        if (taken.count(candidate + suffix))
          return false;
      return true;
    };
    for (int n = 2; !free(stem); ++n)
      stem = base + "-" + std::to_string(n);
    for (const char *suffix : kDumpSuffixes)
      taken.insert(stem + suffix);
    stems.push_back(stem);
  }
  return stems;
}

//===----------------------------------------------------------------------===//
// Paths
//===----------------------------------------------------------------------===//

namespace {

std::string errorText(int error) { return std::strerror(error); }

std::string currentDirectory() {
  char buffer[PATH_MAX];
  if (!getcwd(buffer, sizeof buffer))
    runError("cannot read the current directory: " + errorText(errno));
  return buffer;
}

/// The components of `path`, without empty ones.
std::vector<std::string> components(const std::string &path) {
  std::vector<std::string> parts;
  size_t start = 0;
  while (start <= path.size()) {
    size_t end = path.find('/', start);
    if (end == std::string::npos)
      end = path.size();
    if (end > start)
      parts.push_back(path.substr(start, end - start));
    start = end + 1;
  }
  return parts;
}

std::string parentOf(const std::string &resolved) {
  size_t slash = resolved.rfind('/');
  return slash == 0 || slash == std::string::npos ? "/"
                                                  : resolved.substr(0, slash);
}

std::string join(const std::string &dir, const std::string &name) {
  return dir == "/" ? "/" + name : dir + "/" + name;
}

/// Resolves `parts` from the root: realpath while the components exist,
/// then lexically.
std::string resolveParts(const std::vector<std::string> &parts) {
  std::string resolved = "/";
  bool exists = true;
  for (const std::string &part : parts) {
    if (part == ".")
      continue;
    if (part == "..") {
      resolved = parentOf(resolved);
      continue;
    }
    std::string candidate = join(resolved, part);
    char real[PATH_MAX];
    if (exists && realpath(candidate.c_str(), real)) {
      resolved = real;
    } else {
      exists = false;
      resolved = candidate;
    }
  }
  return resolved;
}

std::string absolute(const std::string &path) {
  return !path.empty() && path[0] == '/' ? path
                                         : currentDirectory() + "/" + path;
}

/// The folder part of `path` as written ("." for a bare name).
std::string folderOf(const std::string &path) {
  size_t slash = path.rfind('/');
  if (slash == std::string::npos)
    return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

} // namespace

std::string resolveOutputPath(const std::string &path) {
  std::vector<std::string> parts = components(absolute(path));
  if (parts.empty())
    return "/";
  std::string last = parts.back();
  parts.pop_back();
  if (last == "." || last == "..") {
    parts.push_back(last);
    return resolveParts(parts);
  }
  return join(resolveParts(parts), last);
}

std::string resolveDirectory(const std::string &path) {
  return resolveParts(components(absolute(path)));
}

//===----------------------------------------------------------------------===//
// OutputPlan
//===----------------------------------------------------------------------===//

OutputPlan::Entry OutputPlan::identify(const std::string &option,
                                       const std::string &path) {
  Entry entry;
  entry.option = option;
  entry.path = path;
  entry.resolved = resolveOutputPath(path);
  struct stat info;
  if (lstat(path.c_str(), &info) == 0) {
    entry.exists = true;
    entry.device = info.st_dev;
    entry.inode = info.st_ino;
  }
  if (stat(path.c_str(), &info) == 0) {
    entry.targetExists = true;
    entry.targetDevice = info.st_dev;
    entry.targetInode = info.st_ino;
  }
  return entry;
}

void OutputPlan::addInput(const std::string &path) {
  Entry input = identify("input", path);
  char real[PATH_MAX];
  if (realpath(path.c_str(), real))
    input.resolved = real;
  inputs.push_back(input);
  // The input's own path too: replacing a symlink given as the input
  // would lose it even though its target stays.
  Entry asWritten = identify("input", path);
  asWritten.targetExists = false;
  inputs.push_back(asWritten);
}

namespace {

/// What kind of file `mode` is, for a message ("a character device").
const char *kindOf(mode_t mode) {
  if (S_ISCHR(mode))
    return "a character device";
  if (S_ISBLK(mode))
    return "a block device";
  if (S_ISFIFO(mode))
    return "a FIFO";
  if (S_ISSOCK(mode))
    return "a socket";
  if (S_ISDIR(mode))
    return "a directory";
  return "no regular file";
}

/// Whether a file can be created in the existing directory `dir`: created
/// and removed again. access() says yes to root on read-only mounts and on
/// /proc and /sys, where creating a file fails after the run.
int probeCreate(const std::string &dir) {
  std::string probe = dir + "/.sim-run-probe-XXXXXX";
  int fd = mkstemp(probe.data());
  if (fd < 0)
    return errno;
  close(fd);
  unlink(probe.c_str());
  return 0;
}

/// Whether a directory can be created in the existing directory
/// `ancestor`: one of an unpredictable name is created and removed. Not the
/// missing directory itself: the ranks of a distributed run check their
/// outputs at once, and one rank's probe must not come and go under
/// another's check.
int probeMakeDirectory(const std::string &ancestor) {
  std::string probe = ancestor + "/.sim-run-probe-XXXXXX";
  if (!mkdtemp(probe.data()))
    return errno;
  rmdir(probe.c_str());
  return 0;
}

} // namespace

void OutputPlan::checkWritableFolder(const std::string &option,
                                     const std::string &dir) const {
  struct stat info;
  if (stat(dir.c_str(), &info) == 0) {
    if (!S_ISDIR(info.st_mode))
      usageError(option + ": '" + dir + "' is not a directory");
    int error = access(dir.c_str(), W_OK | X_OK) != 0 ? errno : 0;
    if (!error)
      error = probeCreate(dir);
    if (error)
      usageError(option + ": cannot write into directory '" + dir +
                 "': " + errorText(error));
    return;
  }
  if (errno != ENOENT && errno != ENOTDIR)
    usageError(option + ": cannot use directory '" + dir +
               "': " + errorText(errno));
  // Missing: its nearest existing ancestor must be a writable directory.
  std::string ancestor = resolveDirectory(dir);
  while (ancestor != "/" && stat(ancestor.c_str(), &info) != 0) {
    if (errno != ENOENT && errno != ENOTDIR)
      usageError(option + ": cannot create directory '" + dir + "': '" +
                 ancestor + "': " + errorText(errno));
    ancestor = parentOf(ancestor);
  }
  if (stat(ancestor.c_str(), &info) != 0 || !S_ISDIR(info.st_mode))
    usageError(option + ": cannot create directory '" + dir + "': '" +
               ancestor + "' is not a directory");
  int error = access(ancestor.c_str(), W_OK | X_OK) != 0 ? errno : 0;
  if (!error)
    error = probeMakeDirectory(ancestor);
  if (error)
    usageError(option + ": cannot create directory '" + dir + "' in '" +
               ancestor + "': " + errorText(error));
}

void OutputPlan::addDirectory(const std::string &option,
                              const std::string &dir) {
  checkWritableFolder(option, dir);
  Entry folder;
  folder.option = option;
  folder.path = dir;
  folder.resolved = folder.folder = resolveDirectory(dir);
  folder.isFolder = true;
  checkFilesAndFolders(folder);
  folders.push_back(folder);
}

void OutputPlan::checkFilesAndFolders(const Entry &added) const {
  // Whether `file`'s path is `folder` or a folder above it.
  auto holds = [](const std::string &file, const std::string &folder) {
    return folder == file || (folder.size() > file.size() &&
                              folder.compare(0, file.size(), file) == 0 &&
                              folder[file.size()] == '/');
  };
  bool addedIsFile = !added.isFolder;
  for (const std::vector<Entry> *list : {&files, &folders})
    for (const Entry &other : *list) {
      bool otherIsFile = !other.isFolder;
      if (addedIsFile && holds(added.resolved, other.folder))
        usageError(added.option + ": '" + added.path + "' is where " +
                   other.option + " needs the folder '" +
                   (otherIsFile ? folderOf(other.path) : other.path) +
                   "' for its output; name another file");
      if (otherIsFile && holds(other.resolved, added.folder))
        usageError(added.option + ": '" +
                   (addedIsFile ? folderOf(added.path) : added.path) +
                   "' must be a folder, but it is where " + other.option +
                   " writes the file '" + other.path +
                   "'; name another folder");
    }
}

void OutputPlan::addFile(const std::string &option, const std::string &path) {
  if (path.empty() || path.back() == '/')
    usageError(option + ": '" + path + "' is a directory, not a file");
  Entry file = identify(option, path);
  // An output replaces what is at its path; where a symlink there points
  // does not matter.
  file.targetExists = false;
  struct stat info;
  if (file.exists && lstat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
    usageError(option + ": '" + path + "' is a directory, not a file");
  // Outputs replace the file at their path (written beside it, then
  // renamed over it): a device, a FIFO or a socket there, or a symlink to
  // one (/dev/stdout), would be replaced by a regular file, which as root
  // breaks /dev/null for the whole machine.
  if (file.exists && lstat(path.c_str(), &info) == 0 &&
      !S_ISREG(info.st_mode) && !S_ISLNK(info.st_mode))
    usageError(option + ": '" + path + "' is " + kindOf(info.st_mode) +
               ", not a regular file; sim-run replaces an output file "
               "whole, so name a regular file");
  // /dev/stdout and /dev/fd/N are symlinks into /proc/self/fd: whatever
  // they lead to (a terminal, a pipe, a file), replacing them would replace
  // the machine's /dev/stdout.
  char target[PATH_MAX];
  ssize_t length =
      file.exists && lstat(path.c_str(), &info) == 0 && S_ISLNK(info.st_mode)
          ? readlink(path.c_str(), target, sizeof target - 1)
          : -1;
  if (length > 0 &&
      std::string_view(target, size_t(length)).substr(0, 6) == "/proc/")
    usageError(option + ": '" + path + "' is a symlink to '" +
               std::string(target, size_t(length)) +
               "', a process's file; sim-run would replace the symlink with "
               "a regular file, so name a regular file");
  if (file.exists && stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode) &&
      !S_ISDIR(info.st_mode))
    usageError(option + ": '" + path + "' is a symlink to " +
               kindOf(info.st_mode) +
               ", not to a regular file; sim-run would replace the symlink "
               "with a regular file, so name a regular file");
  std::string last = path.substr(path.rfind('/') + 1);
  if (last == "." || last == "..")
    usageError(option + ": '" + path + "' is a directory, not a file");
  checkWritableFolder(option, folderOf(path));

  auto same = [](const Entry &a, const Entry &b) {
    if (a.resolved == b.resolved)
      return true;
    if (a.exists && b.exists && a.device == b.device && a.inode == b.inode)
      return true;
    return a.exists && b.targetExists && a.device == b.targetDevice &&
           a.inode == b.targetInode;
  };
  for (const Entry &input : inputs)
    if (same(file, input))
      usageError(option + ": '" + path + "' is the input '" + input.path +
                 "'; sim-run never writes onto its input");
  for (const Entry &other : files)
    if (same(file, other))
      usageError(option + ": '" + path + "' is also the file of " +
                 other.option + " ('" + other.path + "')");
  file.folder = resolveDirectory(folderOf(path));
  checkFilesAndFolders(file);
  files.push_back(file);
}

bool sameFile(const std::string &a, const std::string &b) {
  struct stat first, second;
  if (stat(a.c_str(), &first) == 0 && stat(b.c_str(), &second) == 0)
    return first.st_dev == second.st_dev && first.st_ino == second.st_ino;
  return resolveOutputPath(a) == resolveOutputPath(b);
}

//===----------------------------------------------------------------------===//
// Writing
//===----------------------------------------------------------------------===//

namespace {

mode_t processUmask = 022;

/// Removes a temporary file and its registration when it goes out of scope
/// before it was renamed into place.
class PendingFile {
public:
  explicit PendingFile(std::string path)
      : path(std::move(path)), slot(registerTemporary(this->path.c_str())) {}
  ~PendingFile() {
    if (!renamed)
      unlink(path.c_str());
    unregisterTemporary(slot);
  }
  PendingFile(const PendingFile &) = delete;
  PendingFile &operator=(const PendingFile &) = delete;

  std::string path;
  int slot;
  bool renamed = false;
};

} // namespace

void captureUmask() {
  processUmask = umask(0);
  umask(processUmask);
}

void makeDirectories(const std::string &dir) {
  std::string prefix = !dir.empty() && dir[0] == '/' ? "/" : "";
  for (const std::string &part : components(dir)) {
    prefix += part;
    if (mkdir(prefix.c_str(), 0777) != 0 && errno != EEXIST)
      runError("cannot create directory '" + prefix + "': " + errorText(errno));
    prefix += "/";
  }
  struct stat info;
  if (stat(dir.c_str(), &info) != 0 || !S_ISDIR(info.st_mode))
    runError("'" + dir + "' is not a directory");
}

void writeFileAtomically(const std::string &path, std::string_view contents) {
  writeFileAtomically(path, [&](int fd) {
    const char *data = contents.data();
    size_t left = contents.size();
    while (left > 0) {
      ssize_t written = write(fd, data, left);
      if (written < 0 && errno == EINTR)
        continue;
      if (written <= 0)
        runError("cannot write '" + path + "': " + errorText(errno));
      data += written;
      left -= size_t(written);
    }
  });
}

void writeFileAtomically(const std::string &path,
                         const std::function<void(int fd)> &write) {
  std::string dir = folderOf(path);
  makeDirectories(dir);
  std::string name = dir + "/.sim-run-XXXXXX";
  int fd, mkstempErrno;
  std::optional<PendingFile> pending;
  {
    BlockSignals blocked;
    fd = mkstemp(name.data());
    mkstempErrno = errno;
    if (fd >= 0)
      pending.emplace(name);
  }
  if (fd < 0)
    runError("cannot create a temporary file in '" + dir + "' for '" + path +
             "': " + errorText(mkstempErrno));
  auto fail = [&](const char *what) {
    int error = errno;
    close(fd);
    runError("cannot write '" + path + "' (" + what + " '" + name +
             "'): " + errorText(error));
  };
  if (fchmod(fd, 0666 & ~processUmask) != 0)
    fail("fchmod");
  try {
    write(fd);
  } catch (...) {
    close(fd);
    throw;
  }
  if (fsync(fd) != 0)
    fail("fsync");
  if (close(fd) != 0)
    runError("cannot write '" + path + "' (close '" + name +
             "'): " + errorText(errno));
  if (rename(name.c_str(), path.c_str()) != 0)
    runError("cannot rename '" + name + "' to '" + path +
             "': " + errorText(errno));
  pending->renamed = true;
  // The rename itself, on disk.
  int dirFd = open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dirFd >= 0) {
    fsync(dirFd);
    close(dirFd);
  }
}

void removeStale(const std::string &path) {
  if (unlink(path.c_str()) != 0 && errno != ENOENT)
    runError("cannot remove the stale '" + path + "': " + errorText(errno));
}

} // namespace simrun
