// Reading YAML input so that every problem is reported with file, line and key path, and all
// problems of a file at once (parse everything, then fail once with a ConfigError).
//
// Usage:
//   ConfigFile file = ConfigFile::load("scenario.yaml");
//   ConfigNode root = file.root();
//   root.allowKeys({"start", "imu", "segments"});
//   double lat = root["start"].quantity("latitude", Dimension::angle());
//   ...
//   file.throwIfErrors();
#pragma once

#include <yaml-cpp/yaml.h>

#include <functional>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "common/units.hpp"

namespace sinsim {

class ConfigFile;

/// A view of one YAML node with its key path; problems are recorded in the owning ConfigFile.
/// Accessors never throw for bad input: they record a Diagnostic and return a fallback value, so
/// that parsing goes on and every problem is found.
class ConfigNode {
 public:
  ConfigNode(ConfigFile* file, YAML::Node node, std::string path, int line);
  ConfigNode(const ConfigNode&) = default;
  ConfigNode& operator=(const ConfigNode& other);

  bool exists() const { return node_.IsDefined() && !node_.IsNull(); }
  bool isMap() const { return node_.IsMap(); }
  bool isSequence() const { return node_.IsSequence(); }
  bool isScalar() const { return node_.IsScalar(); }
  const std::string& path() const { return path_; }
  int line() const { return line_; }
  /// The name of the file this node was read from.
  const std::string& fileName() const;
  const YAML::Node& yaml() const { return node_; }

  /// Child of a map (missing child: exists() is false, line is this node's line).
  ConfigNode operator[](const std::string& key) const;
  /// Items of a sequence (records an error when this is not a sequence).
  std::vector<ConfigNode> items() const;
  /// Keys of a map in file order (records an error when this is not a map).
  std::vector<std::string> keys() const;
  bool has(const std::string& key) const;

  /// Records an error for each key not in the list, with a close match when there is one.
  void allowKeys(std::initializer_list<const char*> allowed) const;
  void allowKeys(const std::vector<std::string>& allowed) const;

  /// Required child that must exist (records "missing key" at this node's line).
  ConfigNode require(const std::string& key) const;

  /// Scalar accessors on this node.
  std::optional<std::string> asString() const;
  std::optional<double> asQuantity(Dimension expected) const;
  std::optional<double> asNumber() const;
  std::optional<long long> asInteger() const;
  std::optional<bool> asBool() const;

  /// Child accessors: required when no fallback is given, optional otherwise.
  std::string string(const std::string& key) const;
  std::string string(const std::string& key, const std::string& fallback) const;
  double quantity(const std::string& key, Dimension expected) const;
  double quantity(const std::string& key, Dimension expected, double fallbackSi) const;
  double number(const std::string& key) const;
  double number(const std::string& key, double fallback) const;
  long long integer(const std::string& key) const;
  long long integer(const std::string& key, long long fallback) const;
  bool boolean(const std::string& key, bool fallback) const;
  /// A string that must be one of the choices (the message lists them).
  std::string choice(const std::string& key, const std::vector<std::string>& choices,
                     const std::string& fallback) const;

  /// Records a problem at this node.
  void error(const std::string& message) const;
  /// Is an SI value read from this node within limits::kMaxQuantity (and, for a frequency,
  /// limits::kMaxRate)? Records the problem at this node if not. asQuantity checks it itself.
  bool checkPhysical(double si, Dimension dim) const;
  /// Checks a condition on an already read value; records the message at this node if false.
  bool check(bool ok, const std::string& message) const;

 private:
  ConfigFile* file_;
  YAML::Node node_;
  std::string path_;
  int line_;
};

/// One parsed YAML file and the problems found in it.
class ConfigFile {
 public:
  /// Reads and parses; throws ConfigError at once for: a missing file, a directory or device
  /// file, a file over limits::kMaxYamlBytes, an empty file (the message ends with `emptyHint`,
  /// e.g. how to write an empty model on purpose), and everything fromString refuses.
  static ConfigFile load(const std::string& path, const std::string& emptyHint = "");
  /// Parses text as if it came from the named file (tests, inline models). Throws ConfigError
  /// for a YAML syntax error, a NUL byte, a second document, duplicate keys (naming both lines),
  /// non-scalar keys, and more than limits::kMaxYamlNodeVisits nodes counted through aliases.
  static ConfigFile fromString(const std::string& text, const std::string& name);
  /// A tree built in code rather than read from text (the Python module's dicts): the same
  /// checks as fromString on the tree; diagnostics carry `name` and key paths, no line numbers.
  static ConfigFile fromNode(YAML::Node root, const std::string& name);

  ConfigNode root();
  const std::string& name() const { return name_; }

  void addError(int line, const std::string& key, const std::string& message);
  bool hasErrors() const { return !diagnostics_.empty(); }
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
  /// Throws one ConfigError listing every problem, if there is any.
  void throwIfErrors() const;

 private:
  ConfigFile(YAML::Node root, std::string name) : root_(std::move(root)), name_(std::move(name)) {}
  YAML::Node root_;
  std::string name_;
  bool hasLines_ = true;  // false for a tree built in code (fromNode)
  std::vector<Diagnostic> diagnostics_;
};

/// Joins key paths: ("", "a") → "a", ("a", "b") → "a.b", ("a", "[2]") → "a[2]".
std::string joinKey(const std::string& parent, const std::string& child);

}  // namespace sinsim
