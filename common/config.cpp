#include "common/config.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include <yaml-cpp/eventhandler.h>

#include "common/limits.hpp"
#include "common/read_file.hpp"

namespace sinsim {
namespace {

int lineOf(const YAML::Node& n, int fallback) {
  if (!n.IsDefined()) return fallback;
  int l = n.Mark().line;
  return l >= 0 ? l + 1 : fallback;  // yaml-cpp marks are 0-based
}

// Levenshtein distance, for "did you mean" hints on unknown keys.
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t sub = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string quoteList(const std::vector<std::string>& xs) {
  std::string s;
  for (const auto& x : xs) s += (s.empty() ? "" : ", ") + x;
  return s;
}

}  // namespace

std::string joinKey(const std::string& parent, const std::string& child) {
  if (parent.empty()) return child;
  if (!child.empty() && child.front() == '[') return parent + child;
  return parent + "." + child;
}

// ---------------------------------------------------------------------------------------------
ConfigFile ConfigFile::load(const std::string& path, const std::string& emptyHint) {
  std::string text;
  try {
    text = readRegularFile(path, limits::kMaxYamlBytes, "YAML file");
  } catch (const InputError& e) {
    std::string msg = e.text();
    if (msg.rfind(path + ": ", 0) == 0) msg.erase(0, path.size() + 2);
    throw ConfigError({{path, 0, "", msg}});
  }
  ConfigFile file = fromString(text, path);
  if (!file.root_.IsDefined() || file.root_.IsNull()) {
    std::string msg = "the file is empty (no YAML content)";
    if (!emptyHint.empty()) msg += ": " + emptyHint;
    throw ConfigError({{path, 1, "", msg}});
  }
  return file;
}

namespace {

// 1-based line of the first NUL byte, or 0.
int nulLine(const std::string& text) {
  const std::size_t at = text.find('\0');
  if (at == std::string::npos) return 0;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

// Walks the whole tree once, expanding aliases as a reader would, and reports duplicate keys,
// non-scalar keys, and a tree that expands to more than kMaxYamlNodeVisits nodes (nested
// aliases: "billion laughs"). Iterative: the depth is bounded by yaml-cpp's parser (2000), but
// the stack of a sanitizer build is not to be trusted with it.
std::vector<Diagnostic> checkTree(const YAML::Node& root, const std::string& name) {
  std::vector<Diagnostic> out;
  // An entry with `leave` set closes a container: its position leaves the current path. yaml-cpp
  // accepts an alias inside the node it names (`a: &a [*a]`), a cycle the walk would follow to
  // the node budget (3 s of CPU under the sanitizers: fuzz_scenario); the positions of the
  // containers on the path find it at once.
  struct Entry {
    YAML::Node node;
    bool leave;
    std::size_t frame;  // the node's place in `frames` (its key path)
  };
  // The key path of each node pushed, as links to its parent: a duplicate key is named by its
  // whole path ("gyro.x[0].density"), built only when one is reported. The keys' text lives in
  // the tree, which outlives the walk.
  struct Frame {
    std::size_t parent;
    bool item;             // a sequence's item `index`, else the map's `key`
    std::string_view key;
    std::size_t index;
  };
  std::vector<Frame> frames{{0, false, {}, 0}};
  auto pathOf = [&](std::size_t f) {
    std::vector<std::size_t> chain;
    for (; f != 0; f = frames[f].parent) chain.push_back(f);
    std::string path;
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      const Frame& fr = frames[*it];
      if (fr.item) path += "[" + std::to_string(fr.index) + "]";
      else path += (path.empty() ? "" : ".") + limits::echo(fr.key);
    }
    return path;
  };
  std::vector<Entry> stack{{root, false, 0}};
  std::unordered_set<int> onPath;  // text positions of the open containers (-1: built in code)
  std::size_t visits = 0;
  while (!stack.empty()) {
    Entry e = stack.back();
    stack.pop_back();
    const int pos = e.node.Mark().pos;
    if (e.leave) {
      onPath.erase(pos);
      continue;
    }
    const YAML::Node& n = e.node;
    if (++visits > limits::kMaxYamlNodeVisits) {
      out.push_back({name, 0, "",
                     "the document expands (through its aliases) to more than " +
                         std::to_string(limits::kMaxYamlNodeVisits) +
                         " nodes; see docs/limits.md"});
      return out;
    }
    if ((n.IsSequence() || n.IsMap()) && pos >= 0) {
      if (!onPath.insert(pos).second) {
        out.push_back({name, lineOf(n, 0), "",
                       "an alias refers to a node that contains it (a structure without end)"});
        return out;
      }
      stack.push_back({n, true, e.frame});
    }
    if (n.IsSequence()) {
      for (std::size_t i = n.size(); i-- > 0;) {
        frames.push_back({e.frame, true, {}, i});
        stack.push_back({n[i], false, frames.size() - 1});
      }
    } else if (n.IsMap()) {
      std::unordered_map<std::string, int> seen;  // key -> line; hashed: a map may be huge
      for (const auto& kv : n) {
        if (!kv.first.IsScalar()) {
          out.push_back({name, lineOf(kv.first, 0), "", "a map key must be a plain name"});
          continue;
        }
        const int line = lineOf(kv.first, 0);
        const auto [it, fresh] = seen.emplace(kv.first.Scalar(), line);
        const std::string& key = kv.first.Scalar();
        frames.push_back({e.frame, false, key, 0});
        if (!fresh)
          out.push_back({name, line, pathOf(frames.size() - 1),
                         "duplicate key (first given at " + name + ":" +
                             std::to_string(it->second) + ")"});
        stack.push_back({kv.second, false, frames.size() - 1});
      }
    }
  }
  return out;
}

/// Where each document starts, and its first node (nothing is built).
struct DocumentStarts : YAML::EventHandler {
  std::vector<YAML::Mark> starts, firstNodes;
  void OnDocumentStart(const YAML::Mark& mark) override { starts.push_back(mark); }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& m, YAML::anchor_t) override { node(m); }
  void OnAlias(const YAML::Mark& m, YAML::anchor_t) override { node(m); }
  void OnScalar(const YAML::Mark& m, const std::string&, YAML::anchor_t,
                const std::string&) override {
    node(m);
  }
  void OnSequenceStart(const YAML::Mark& m, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    node(m);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& m, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    node(m);
  }
  void OnMapEnd() override {}
  void node(const YAML::Mark& m) {
    if (firstNodes.size() < starts.size()) firstNodes.push_back(m);
  }
};

/// Refuses a second document, parsing at most two. yaml-cpp 0.7's LoadAll loops for ever,
/// allocating, on a stray ',' in block context (", a" yields empty documents without consuming
/// the token: yaml-cpp issue 1040, fixed upstream by PR 1319; found by fuzz_config). A second
/// document that starts where the first did is that stuck parser, reported as a syntax error.
void checkSingleDocument(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  DocumentStarts events;
  for (int k = 0; k < 2 && parser.HandleNextDocument(events); ++k) {
  }
  if (events.starts.size() < 2) return;
  const YAML::Mark& second = events.starts[1];
  if (second.pos == events.starts[0].pos)
    throw ConfigError({{name, second.line + 1, "",
                        "YAML syntax error: unexpected character at column " +
                            std::to_string(second.column + 1) + " (a stray ',' ?)"}});
  const YAML::Mark at = events.firstNodes.size() > 1 ? events.firstNodes[1] : second;
  throw ConfigError({{name, at.line + 1, "",
                      "a second YAML document (after ---): one file holds one document"}});
}

}  // namespace

ConfigFile ConfigFile::fromString(const std::string& text, const std::string& name) {
  if (const int line = nulLine(text))
    throw ConfigError({{name, line, "",
                        "a NUL byte (\\x00) in the text: not a YAML file (binary or UTF-16?)"}});
  YAML::Node root;
  try {
    checkSingleDocument(text, name);
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ConfigError({{name, e.mark.line >= 0 ? e.mark.line + 1 : 0, "",
                        "YAML syntax error: " + e.msg}});
  }
  std::vector<Diagnostic> problems = checkTree(root, name);
  if (!problems.empty()) throw ConfigError(problems);
  return ConfigFile(root, name);
}

ConfigFile ConfigFile::fromNode(YAML::Node root, const std::string& name) {
  std::vector<Diagnostic> problems = checkTree(root, name);
  if (!problems.empty()) throw ConfigError(problems);
  ConfigFile file(std::move(root), name);
  file.hasLines_ = false;
  return file;
}

ConfigNode ConfigFile::root() {
  return ConfigNode(this, root_, "", hasLines_ ? lineOf(root_, 1) : 0);
}

void ConfigFile::addError(int line, const std::string& key, const std::string& message) {
  diagnostics_.push_back({name_, line, key, message});
}

void ConfigFile::throwIfErrors() const {
  if (!diagnostics_.empty()) throw ConfigError(diagnostics_);
}

// ---------------------------------------------------------------------------------------------
ConfigNode::ConfigNode(ConfigFile* file, YAML::Node node, std::string path, int line)
    : file_(file), node_(std::move(node)), path_(std::move(path)), line_(line) {}

ConfigNode& ConfigNode::operator=(const ConfigNode& other) {
  // YAML::Node::operator= would overwrite the document's value; rebind the handle instead.
  file_ = other.file_;
  node_.reset(other.node_);
  path_ = other.path_;
  line_ = other.line_;
  return *this;
}

ConfigNode ConfigNode::operator[](const std::string& key) const {
  // Const access: a non-const yaml-cpp operator[] would insert the key into the document.
  // A missing key yields a yaml-cpp "zombie" node whose every accessor throws; hand out a valid
  // Undefined node instead, so that children of missing children can be asked for safely.
  const YAML::Node& self = node_;
  auto pick = [&]() -> YAML::Node {
    if (self.IsDefined() && self.IsMap()) {
      YAML::Node c = self[key];
      if (c.IsDefined()) return c;
    }
    return YAML::Node(YAML::NodeType::Undefined);
  };
  YAML::Node child = pick();
  return ConfigNode(file_, child, joinKey(path_, key), lineOf(child, line_));
}

std::vector<ConfigNode> ConfigNode::items() const {
  std::vector<ConfigNode> out;
  if (!node_.IsSequence()) {
    error("expected a list");
    return out;
  }
  for (std::size_t i = 0; i < node_.size(); ++i) {
    const YAML::Node& self = node_;
    YAML::Node c = self[i];
    out.emplace_back(file_, c, joinKey(path_, "[" + std::to_string(i) + "]"), lineOf(c, line_));
  }
  return out;
}

std::vector<std::string> ConfigNode::keys() const {
  std::vector<std::string> out;
  if (!node_.IsMap()) {
    error("expected a map of key: value");
    return out;
  }
  for (const auto& kv : node_) out.push_back(kv.first.as<std::string>());
  return out;
}

bool ConfigNode::has(const std::string& key) const { return (*this)[key].exists(); }

void ConfigNode::allowKeys(std::initializer_list<const char*> allowed) const {
  allowKeys(std::vector<std::string>(allowed.begin(), allowed.end()));
}

void ConfigNode::allowKeys(const std::vector<std::string>& allowed) const {
  if (!node_.IsDefined() || node_.IsNull()) return;
  if (!node_.IsMap()) {
    error("expected a map with keys " + quoteList(allowed));
    return;
  }
  for (const auto& kv : node_) {
    std::string k = kv.first.as<std::string>();
    if (std::find(allowed.begin(), allowed.end(), k) != allowed.end()) continue;
    std::string hint;
    std::size_t best = 3;
    for (const auto& a : allowed) {
      std::size_t d = editDistance(k, a);
      if (d < best) {
        best = d;
        hint = a;
      }
    }
    std::string msg = "unknown key";
    msg += hint.empty() ? " (known here: " + quoteList(allowed) + ")"
                        : " (did you mean \"" + hint + "\"? known here: " + quoteList(allowed) + ")";
    file_->addError(lineOf(kv.first, line_), joinKey(path_, limits::echo(k)), msg);
  }
}

ConfigNode ConfigNode::require(const std::string& key) const {
  ConfigNode c = (*this)[key];
  if (!c.exists()) file_->addError(line_, c.path(), "missing key");
  return c;
}

const std::string& ConfigNode::fileName() const { return file_->name(); }

void ConfigNode::error(const std::string& message) const {
  file_->addError(line_, path_, message);
}

bool ConfigNode::check(bool ok, const std::string& message) const {
  if (!ok) error(message);
  return ok;
}

std::optional<std::string> ConfigNode::asString() const {
  if (!node_.IsScalar()) {
    error("expected a single value");
    return std::nullopt;
  }
  return node_.Scalar();
}

std::optional<double> ConfigNode::asQuantity(Dimension expected) const {
  auto s = asString();
  if (!s) return std::nullopt;
  double v = 0.0;
  try {
    v = parseQuantityAs(*s, expected);
  } catch (const InputError& e) {
    error(e.text());
    return std::nullopt;
  }
  if (!checkPhysical(v, expected)) return std::nullopt;
  return v;
}

bool ConfigNode::checkPhysical(double si, Dimension dim) const {
  const std::string text = limits::echo(node_.IsScalar() ? node_.Scalar() : std::string());
  if (!(std::abs(si) <= limits::kMaxQuantity)) {
    error("\"" + text + "\" is beyond any physical value here (|x| <= " +
          limits::fmt(limits::kMaxQuantity) + " " + dim.siUnit() + "; docs/limits.md)");
    return false;
  }
  if (dim == Dimension::frequency() && si > limits::kMaxRate) {
    error("\"" + text + "\" is faster than any IMU or process rate (at most " +
          limits::fmt(limits::kMaxRate) + " Hz; docs/limits.md)");
    return false;
  }
  return true;
}

std::optional<double> ConfigNode::asNumber() const {
  return asQuantity(Dimension::none());
}

std::optional<long long> ConfigNode::asInteger() const {
  auto s = asString();
  if (!s) return std::nullopt;
  try {
    std::size_t used = 0;
    long long v = std::stoll(*s, &used);
    if (used == s->size()) return v;
  } catch (const std::exception&) {
  }
  error("expected an integer, got \"" + limits::echo(*s) + "\"");
  return std::nullopt;
}

std::optional<bool> ConfigNode::asBool() const {
  auto s = asString();
  if (!s) return std::nullopt;
  if (*s == "true" || *s == "yes" || *s == "on") return true;
  if (*s == "false" || *s == "no" || *s == "off") return false;
  error("expected true or false, got \"" + limits::echo(*s) + "\"");
  return std::nullopt;
}

std::string ConfigNode::string(const std::string& key) const {
  return require(key).exists() ? (*this)[key].asString().value_or("") : "";
}
std::string ConfigNode::string(const std::string& key, const std::string& fallback) const {
  ConfigNode c = (*this)[key];
  return c.exists() ? c.asString().value_or(fallback) : fallback;
}
double ConfigNode::quantity(const std::string& key, Dimension expected) const {
  ConfigNode c = require(key);
  return c.exists() ? c.asQuantity(expected).value_or(NAN) : NAN;
}
double ConfigNode::quantity(const std::string& key, Dimension expected, double fallbackSi) const {
  ConfigNode c = (*this)[key];
  return c.exists() ? c.asQuantity(expected).value_or(fallbackSi) : fallbackSi;
}
double ConfigNode::number(const std::string& key) const {
  ConfigNode c = require(key);
  return c.exists() ? c.asNumber().value_or(NAN) : NAN;
}
double ConfigNode::number(const std::string& key, double fallback) const {
  ConfigNode c = (*this)[key];
  return c.exists() ? c.asNumber().value_or(fallback) : fallback;
}
long long ConfigNode::integer(const std::string& key) const {
  ConfigNode c = require(key);
  return c.exists() ? c.asInteger().value_or(0) : 0;
}
long long ConfigNode::integer(const std::string& key, long long fallback) const {
  ConfigNode c = (*this)[key];
  return c.exists() ? c.asInteger().value_or(fallback) : fallback;
}
bool ConfigNode::boolean(const std::string& key, bool fallback) const {
  ConfigNode c = (*this)[key];
  return c.exists() ? c.asBool().value_or(fallback) : fallback;
}
std::string ConfigNode::choice(const std::string& key, const std::vector<std::string>& choices,
                               const std::string& fallback) const {
  ConfigNode c = (*this)[key];
  if (!c.exists()) return fallback;
  auto s = c.asString();
  if (!s) return fallback;
  if (std::find(choices.begin(), choices.end(), *s) == choices.end()) {
    c.error("\"" + limits::echo(*s) + "\" is not one of: " + quoteList(choices));
    return fallback;
  }
  return *s;
}

}  // namespace sinsim
