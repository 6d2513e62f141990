// Output files that appear whole or not at all: each is written to a hidden temporary in the
// target folder and renamed over its final name by commit(). Without commit() (an exception on
// the way) the temporaries are removed, and a folder this object created is removed if empty.
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace sinsim::sim {

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

}  // namespace sinsim::sim
