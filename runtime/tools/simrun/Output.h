//===- Output.h - the files sim-run writes ----------------------*- C++ -*-===//
//
// sim-run's outputs (--json FILE, --dump DIR and the .npy files in it) are
// planned and checked before the run: every folder exists or can be
// created and is writable, no output lands on an input (compared by device
// and inode, and by resolved path, also for files that do not exist yet)
// or on another output. A file is written to a temporary file that mkstemp
// creates in the destination folder, fsync'ed and renamed over the
// destination, so a reader sees the old file or the whole new one, and an
// existing symlink there is replaced, never followed. Dump files are named
// after buffers through sanitiseName, so that no buffer name can leave the
// folder or make an odd file name.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUN_OUTPUT_H
#define SIM_RUN_OUTPUT_H

#include <functional>
#include <string>
#include <string_view>
#include <sys/types.h>
#include <vector>

namespace simrun {

/// The longest stem sanitiseName returns, so that a stem, a "-N" to make it
/// unique and the longest suffix fit in a file name (NAME_MAX, 255 bytes).
constexpr size_t kMaxStem = 200;

/// The file-name stem of a buffer's dump files: the bytes A-Z, a-z, 0-9,
/// '_', '.' and '-' are kept, every other byte (a '/', a control character,
/// any byte of a multi-byte or invalid UTF-8 sequence, '%' itself) becomes
/// %XX with upper-case hex digits, and so does a leading '.'; an empty name
/// is "_". The result is cut to kMaxStem bytes (never inside a %XX). Two
/// names give the same stem only when one was cut or empty.
std::string sanitiseName(std::string_view name);

/// The suffixes of a buffer's dump files: its state, --reference's and
/// --check's.
constexpr const char *kDumpSuffixes[] = {".npy", ".reference.npy",
                                         ".check.npy"};

/// The stems of the dump files of `names`, in order: sanitiseName, then
/// "-2", "-3", ... appended to a stem until none of its files (stem + each
/// of kDumpSuffixes) is a file of an earlier stem. So a buffer "X.reference"
/// does not overwrite buffer X's "X.reference.npy".
std::vector<std::string> dumpStems(const std::vector<std::string> &names);

/// `path` made absolute, with the symlinks of its existing folders resolved
/// and "." and ".." applied; the last component is kept as it is (a symlink
/// there is what a rename replaces). Components past the first that does
/// not exist are taken as written.
std::string resolveOutputPath(const std::string &path);
/// The same for a folder: every component resolved.
std::string resolveDirectory(const std::string &path);

/// The outputs of one sim-run, checked before anything runs. Every check
/// that fails is a usage error (exit status 2) naming the option.
class OutputPlan {
public:
  /// An input: no output may be written onto it.
  void addInput(const std::string &path);

  /// --dump DIR: a folder that exists or can be created, and is writable.
  void addDirectory(const std::string &option, const std::string &dir);

  /// A file to write (not a folder, in a folder as addDirectory requires,
  /// not an input, not an output already planned). `option` names it in
  /// messages ("--json", "--dump (buffer 'X')").
  void addFile(const std::string &option, const std::string &path);

private:
  struct Entry {
    /// `folder`: for a file, the folder it goes into, resolved; for a
    /// folder (--dump), the folder itself.
    std::string option, path, resolved, folder;
    /// A folder (--dump) rather than a file.
    bool isFolder = false;
    /// lstat's identity of the path (a file, or the symlink there), and
    /// for inputs stat's too (what the symlink points to).
    bool exists = false;
    dev_t device = 0;
    ino_t inode = 0;
    bool targetExists = false;
    dev_t targetDevice = 0;
    ino_t targetInode = 0;
  };
  static Entry identify(const std::string &option, const std::string &path);
  void checkWritableFolder(const std::string &option,
                           const std::string &dir) const;
  /// No planned file may be where a planned folder is, or above one: the
  /// folder could not be made, or the file could not replace it.
  void checkFilesAndFolders(const Entry &added) const;

  std::vector<Entry> inputs, files, folders;
};

/// Creates `dir` and its missing parents (like mkdir -p).
void makeDirectories(const std::string &dir);

/// Writes `contents` to `path`: a temporary file from mkstemp in the same
/// folder (created if missing), fsync, rename over `path`, fsync of the
/// folder. The temporary file is removed on failure, and by the signal
/// handler if a second signal kills the process meanwhile. A failure is
/// Exit{1} naming the path.
void writeFileAtomically(const std::string &path, std::string_view contents);

/// The same with the contents written by `write` into the temporary file's
/// descriptor (open for reading and writing at offset 0, seekable), for
/// files made piece by piece (the .npz of --output, a checkpoint). `write`
/// reports its own failures (Exit{1}); the temporary file is removed then.
void writeFileAtomically(const std::string &path,
                         const std::function<void(int fd)> &write);

/// Whether two paths name the same file: the same device and inode (a hard
/// link, a symlink to it) or, for files that do not exist yet, the same
/// resolved path.
bool sameFile(const std::string &a, const std::string &b);

/// Removes `path` if it is there (a stale output of an earlier run that
/// this run did not produce again); a failure is Exit{1}.
void removeStale(const std::string &path);

/// Takes the process's umask once, before any thread exists (the files
/// writeFileAtomically makes get 0666 & ~umask, like any new file).
void captureUmask();

} // namespace simrun

#endif // SIM_RUN_OUTPUT_H
