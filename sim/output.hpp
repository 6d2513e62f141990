// Output files that appear whole or not at all: each is written to a hidden temporary in the
// target folder and renamed over its final name by commit(). Without commit() (an exception on
// the way) the temporaries are removed, and a folder this object created is removed if empty.
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace sinsim::sim {

/// A CSV field as written: quoted (with doubled quotes) when it holds a comma, quote or newline —
/// model labels may ("x without gyro.x[0].ar").
std::string csvField(const std::string& s);

class OutputFiles {
 public:
  /// Creates dir (and parents) when missing; throws InputError when it cannot.
  explicit OutputFiles(const std::string& dir);
  ~OutputFiles();
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  /// Opens `name` (inside dir) for writing; the handle stays valid until commit() or destruction.
  std::FILE* open(const std::string& name);
  /// Flushes, closes and renames every file into place; throws Error on an I/O failure.
  void commit();

  const std::string& dir() const { return dir_; }

 private:
  struct File {
    std::string finalPath, tempPath;
    std::FILE* fp = nullptr;
  };
  void discard() noexcept;
  std::string dir_;
  bool createdDir_ = false;
  bool committed_ = false;
  std::vector<File> files_;
};

/// An advisory lock (flock) on an output folder, held for the object's lifetime, so that two
/// sinsim processes never write into one folder at once (the second is refused, even with
/// --resume). Advisory: it guards against sinsim, not against other programs.
class FolderLock {
 public:
  /// Locks the existing folder dir; throws InputError when another process holds it.
  explicit FolderLock(const std::string& dir);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

/// Removes the temporaries a killed sinsim left in dir (and its subfolders when recursive): files
/// named as sinsim names them (".NAME.tmp.PID", "NAME.tmp.PID.THREAD"), nothing else. Call only
/// while holding the folder's FolderLock. Returns how many were removed.
std::size_t removeStaleTemporaries(const std::string& dir, bool recursive);

/// "cannot write PATH: <strerror(err)>", with a hint for a full disk or a file size limit
/// (ulimit -f; sinsim ignores SIGXFSZ so that the write fails with EFBIG instead of killing it).
std::string writeErrorMessage(const std::string& path, int err);

}  // namespace sinsim::sim
