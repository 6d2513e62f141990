// Opening input files safely: only regular files (a directory, /dev/zero or a FIFO where a file
// is expected is refused by name), and never more than a stated number of bytes.
#pragma once

#include <cstddef>
#include <string>

namespace sinsim {

/// Throws InputError "PATH: ..." unless PATH names an existing regular file (symlinks followed).
/// `what` says what the file was expected to be ("model file", "record").
void requireRegularFile(const std::string& path, const std::string& what);

/// Reads a whole regular file of at most maxBytes bytes; throws InputError naming the file
/// otherwise (missing, unreadable, a directory or device, too large).
std::string readRegularFile(const std::string& path, std::size_t maxBytes,
                            const std::string& what);

/// From now on, every file requireRegularFile accepts is remembered as an input of this process
/// (a command line run: one command), and requireNotAnInput refuses to write over one: `fit
/// rec.csv -o rec.csv` replaced the record with the model. Off by default (a Python session
/// rewrites its own files on purpose).
void trackInputFiles();
/// Throws InputError "cannot write PATH: ..." when PATH is (a link to) a remembered input.
void requireNotAnInput(const std::string& path);

/// Tracks the inputs of one library call (a Python function) for its lifetime: within it an
/// output never replaces a file it read (`sinsim.analyze("rec.csv", json="rec.csv")` replaced the
/// record), while the session may rewrite its files between calls. Scopes may overlap (threads):
/// the inputs are forgotten when the last one ends.
class InputFilesScope {
 public:
  InputFilesScope();
  ~InputFilesScope();
  InputFilesScope(const InputFilesScope&) = delete;
  InputFilesScope& operator=(const InputFilesScope&) = delete;
};

/// Refuses, from now on, every input file outside `dir` (fuzzing harnesses: a fuzzed scenario
/// must not read arbitrary paths such as `errors: /etc/shadow`). Empty: no restriction.
void restrictInputFilesTo(const std::string& dir);

}  // namespace sinsim
