// Output files that appear whole or not at all: written to a hidden temporary in the target's
// folder (".NAME.tmp.PID.N") and renamed over the final name, which POSIX rename(2) makes atomic.
// On any failure, or when an AtomicFile is destroyed without commit(), the temporary is removed
// and an existing file at the target is left untouched.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace sinsim {

/// Throws InputError unless `path` can be written: its folder exists and is writable, and the
/// name is not a folder, a device, a pipe or an input of this command. Commands call it for every
/// output before their work, so that a bad output name never costs the work or leaves some
/// outputs written and others not.
void requireWritableTarget(const std::string& path);

/// requireWritableTarget for each of a command's outputs (an empty name is an output not asked
/// for), and no two of them the same file: `--json r --html r` would keep only the last written.
void requireWritableTargets(const std::vector<std::string>& paths);

/// Writes `text` to `path` atomically. Throws InputError when the folder does not exist or the
/// temporary cannot be created, Error on a write or rename failure.
void writeFileAtomic(const std::string& path, std::string_view text);

/// The streaming form: write through file(), then commit(). Not copyable; movable.
class AtomicFile {
 public:
  /// Creates the temporary beside `path` (mode 0666 less the umask, like fopen).
  /// Throws InputError when the folder does not exist or is not writable.
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(AtomicFile&& other) noexcept;
  AtomicFile& operator=(AtomicFile&&) = delete;
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// The open temporary (binary mode); valid until commit() or destruction.
  std::FILE* file() const { return fp_; }
  /// Flushes, closes and renames the temporary over the target. Throws Error on an I/O failure
  /// (after removing the temporary).
  void commit();

  const std::string& path() const { return path_; }
  const std::string& tempPath() const { return temp_; }

 private:
  void discard() noexcept;
  std::string path_, temp_;
  std::FILE* fp_ = nullptr;
};

}  // namespace sinsim
