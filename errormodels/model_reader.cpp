// The one reader of the error-model format: YAML → ErrorModelSpec (model_io.hpp).
#include <cmath>
#include <fstream>
#include <sstream>

#include "common/limits.hpp"
#include "common/read_file.hpp"
#include "errormodels/effect.hpp"
#include "errormodels/model_io.hpp"

namespace sinsim::errormodels {
namespace {

// "expected a value in deg/s" or the schema's own words, with example units filled in.
std::string expectedWords(const ParamSchema& s, Sensor sensor, int item) {
  std::string a = exampleUnit(s.dim.of(sensor, item));
  std::string b = s.hasAlt ? exampleUnit(s.alt.of(sensor, item)) : "";
  if (s.expecting.empty()) return "a value in " + a + (s.hasAlt ? " or " + b : "");
  std::string w = s.expecting;
  for (auto [ph, unit] : {std::pair<std::string, std::string>{"{0}", a}, {"{1}", b}}) {
    auto at = w.find(ph);
    if (at != std::string::npos) w.replace(at, ph.size(), unit);
  }
  return w;
}

// One value of a parameter item: SI and its dimension, or nullopt (problem recorded).
std::optional<std::pair<double, Dimension>> readValue(const ConfigNode& n, const ParamSchema& s,
                                                      Sensor sensor, int item) {
  const Dimension want = s.dim.of(sensor, item);
  if (!s.hasAlt && !s.plainZero) {  // the common case: ConfigNode's own message
    auto v = n.asQuantity(want);
    if (!v) return std::nullopt;
    return std::make_pair(*v, want);
  }
  auto text = n.asString();
  if (!text) return std::nullopt;
  try {
    Quantity q = parseQuantity(*text);
    if (s.accepts(q.dim, sensor, item) && (q.dim != Dimension::none() || !s.plainZero ||
                                           q.si == 0.0 || want == Dimension::none())) {
      if (!n.checkPhysical(q.si, q.dim)) return std::nullopt;
      return std::make_pair(q.si, q.dim);
    }
    n.error("expected " + expectedWords(s, sensor, item) + ", got \"" + *text + "\"");
  } catch (const InputError& e) {
    n.error(e.text());
  }
  return std::nullopt;
}

SourceLocation locationOf(const ConfigNode& n, const std::string& file) {
  SourceLocation w;
  w.file = file;
  w.line = n.line();
  w.key = n.path();
  if (n.isScalar()) w.text = n.asString().value_or("");
  return w;
}

// Converts one parameter by its schema; nullopt when the YAML cannot be converted (recorded).
std::optional<ParamSpec> readParam(const ConfigNode& n, const ParamSchema& s, Sensor sensor,
                                   const std::string& file) {
  ParamSpec p;
  p.key = s.key;
  p.kind = s.kind;
  p.where = locationOf(n, file);
  bool ok = true;
  auto add = [&](const ConfigNode& item, int k) {
    auto v = readValue(item, s, sensor, k);
    ok = ok && v.has_value();
    if (v) p.values.push_back(v->first), p.dims.push_back(v->second);
  };
  switch (s.kind) {
    case ParamKind::quantity: add(n, 0); break;
    case ParamKind::list: {
      if (!n.isSequence()) {
        n.error("expected a list, e.g. [1, 2]");
        return std::nullopt;
      }
      auto items = n.items();
      if (s.count > 0 && int(items.size()) != s.count) {
        n.error("expected " + std::to_string(s.count) + " values, got " +
                std::to_string(items.size()));
        return std::nullopt;
      }
      if (items.empty()) {
        n.error("expected at least one value");
        return std::nullopt;
      }
      for (std::size_t k = 0; k < items.size(); ++k) add(items[k], int(k));
      break;
    }
    case ParamKind::matrix: {
      auto rows = n.items();
      if (!n.isSequence()) return std::nullopt;
      if (rows.size() != 3) {
        n.error("expected 3 rows, got " + std::to_string(rows.size()));
        return std::nullopt;
      }
      for (const auto& row : rows) {
        auto cols = row.items();
        if (cols.size() != 3) {
          row.error("expected a row of 3 values");
          return std::nullopt;
        }
        for (const auto& c : cols) add(c, 0);
      }
      break;
    }
    case ParamKind::text: {
      auto t = n.asString();
      if (!t) return std::nullopt;
      p.text = *t;
      break;
    }
    case ParamKind::flag: {
      auto b = n.asBool();
      if (!b) return std::nullopt;
      p.flag = *b;
      break;
    }
  }
  if (!ok) return std::nullopt;
  return p;
}

// Records an effect's problems at the nodes they name.
void record(const ConfigNode& item, const SpecProblems& problems) {
  for (const auto& [key, message] : problems.items) {
    if (key.empty()) {
      item.error(message);
      continue;
    }
    const auto bracket = key.find('[');
    const std::string head = key.substr(0, bracket);
    ConfigNode n = item[head];
    if (bracket != std::string::npos && n.isSequence()) {
      const auto idx = std::size_t(std::stoul(key.substr(bracket + 1)));
      auto items = n.items();
      if (idx < items.size()) n = items[idx];
    }
    if (n.exists() || key == head) {
      n.error(message);
    } else {
      item.error(message);
    }
  }
}

// "gyro" / "accel" "triad" "all" "x": where an effect can sit; the scope check of the registry.
std::optional<EffectSpec> readEffect(const ConfigNode& item, Sensor sensor, EffectList list,
                                     int index, const std::string& file) {
  if (!item.isMap()) {
    item.error("expected an effect, e.g. {type: white, density: 0.2 deg/sqrt(h)}");
    return std::nullopt;
  }
  std::string type = item.string("type");
  if (type.empty()) return std::nullopt;
  const EffectType* et = findEffectType(type);
  if (!et) {
    item["type"].error("unknown effect type \"" + type + "\" (known: " + knownEffectTypes() + ")");
    return std::nullopt;
  }
  const bool triadList = list == EffectList::triad;
  if (et->scope == Scope::triad && !triadList) {
    item["type"].error(type + " acts on the whole triad: put it under " + sensorName(sensor) +
                       ".triad");
    return std::nullopt;
  }
  if (et->scope == Scope::axis && triadList) {
    item["type"].error(type + " acts on one axis: put it under " + sensorName(sensor) +
                       ".x, .y, .z or .all");
    return std::nullopt;
  }
  const auto& schema = et->params();
  std::vector<std::string> allowed = {"type", "enabled", "note"};
  for (const auto& s : schema) allowed.push_back(s.key);
  item.allowKeys(allowed);

  EffectSpec e;
  e.type = type;
  e.where = locationOf(item, file);
  e.enabled = item.boolean("enabled", true);
  e.note = item.string("note", "");
  bool converted = true;
  for (const std::string& key : item.keys()) {
    for (const auto& s : schema) {
      if (s.key != key) continue;
      auto p = readParam(item[key], s, sensor, file);
      converted = converted && p.has_value();
      if (p) e.parameters.push_back(std::move(*p));
    }
  }
  // The same checks ImuErrorModel::fromSpec makes, here with the file's lines at hand.
  SpecProblems problems;
  EffectSite site;
  site.sensor = sensor;
  site.axis = triadList ? -1 : 0;
  site.index = index;
  site.name = item.path() + "." + type;
  if (converted) {
    if (checkParameters(e, schema, sensor, problems)) et->build(e, site, problems);
  } else {
    // Only the presence checks: a key whose value was refused still counts as given.
    EffectSpec present = e;
    for (const std::string& key : item.keys())
      if (!present.has(key) && key != "type" && key != "enabled" && key != "note")
        present.parameters.push_back(ParamSpec::textValue(key, ""));
    SpecProblems all;
    checkParameters(present, schema, sensor, all);
    for (const auto& pr : all.items)
      if (pr.second.rfind("missing", 0) == 0 || pr.second.rfind("give only", 0) == 0)
        problems.add(pr.first, pr.second);
  }
  record(item, problems);
  if (!converted) return std::nullopt;
  return e;
}

void readList(const ConfigNode& node, Sensor sensor, EffectList list, SensorSpec& out,
              const std::string& file) {
  if (!node.exists()) {
    if (node.yaml().IsNull()) out.keepEmpty[int(list)] = true;  // `x:` with nothing after it
    return;
  }
  const auto items = node.items();
  for (std::size_t i = 0; i < items.size(); ++i)
    if (auto e = readEffect(items[i], sensor, list, int(i), file)) out.list(list).push_back(*e);
  out.keepEmpty[int(list)] = items.empty();
}

}  // namespace

ErrorModelSpec readErrorModel(const ConfigNode& node) {
  ErrorModelSpec spec;
  spec.source = "inline";
  if (!node.exists()) return spec;
  if (!node.isMap()) {
    node.error("expected an error model: a map with keys gyro and/or accel");
    return spec;
  }
  node.allowKeys({"description", "record_duration", "gyro", "accel"});
  spec.description = node.string("description", "");
  if (node.has("record_duration")) {
    const double d = node.quantity("record_duration", Dimension::time());
    if (std::isfinite(d) && d > 0.0)
      spec.recordDuration = d;
    else
      node["record_duration"].error("expected a positive duration (the fitted record's length), e.g. 40 min");
  }
  // `gyro: ~` or a file of only `description:` would silently be a perfect IMU.
  if (!node.yaml()["gyro"] && !node.yaml()["accel"])
    node.error("no gyro: or accel: section: an empty error model; write `gyro: {}` if you mean a "
               "perfect IMU");
  for (Sensor sensor : {Sensor::gyro, Sensor::accel}) {
    ConfigNode sn = node[sensorName(sensor)];
    if (node.yaml()[sensorName(sensor)] && !sn.exists())
      sn.error("no effects given (write `" + std::string(sensorName(sensor)) +
               ": {}` for a perfect sensor)");
    if (!sn.exists()) continue;
    if (!sn.isMap()) {
      sn.error("expected a map with keys triad, all, x, y, z (each a list of effects)");
      continue;
    }
    sn.allowKeys({"triad", "all", "x", "y", "z"});
    for (EffectList l : {EffectList::triad, EffectList::all, EffectList::x, EffectList::y,
                         EffectList::z})
      if (sn.has(listName(l)) || sn.yaml()[listName(l)])
        readList(sn[listName(l)], sensor, l, spec.sensor(sensor), node.fileName());
  }
  std::size_t effects = 0;
  for (Sensor sensor : {Sensor::gyro, Sensor::accel})
    for (EffectList l : {EffectList::triad, EffectList::all, EffectList::x, EffectList::y,
                         EffectList::z})
      effects += spec.sensor(sensor).list(l).size();
  if (effects > limits::kMaxModelEffects)
    node.error(std::to_string(effects) + " effects: more than the " +
               std::to_string(limits::kMaxModelEffects) + " a model may hold (docs/limits.md)");
  return spec;
}

}  // namespace sinsim::errormodels

// ---- comments and files -----------------------------------------------------------------------
namespace sinsim::errormodels {
namespace {

bool isComment(const std::string& line) {
  const auto at = line.find_first_not_of(" \t");
  return at != std::string::npos && line[at] == '#';
}
// A block-sequence item ("    - {type: ...}") or a block-style empty list ("    []"): the lines whose
// neighbouring comments belong to them (a flow list on its key's line has none of its own).
bool startsWith(const std::string& line, char c) {
  const auto at = line.find_first_not_of(" \t");
  return at != std::string::npos && line[at] == c;
}
bool isBlank(const std::string& line) { return line.find_first_not_of(" \t\r") == std::string::npos; }
std::size_t indentOf(const std::string& line) { return line.find_first_not_of(" \t"); }
// "# text" → "text" (one space after the hash dropped).
std::string commentText(const std::string& line) {
  std::string t = line.substr(line.find('#') + 1);
  if (!t.empty() && t[0] == ' ') t.erase(0, 1);
  while (!t.empty() && (t.back() == '\r' || t.back() == ' ')) t.pop_back();
  return t;
}

// The comment lines directly above line `line` (1-based), in file order.
std::vector<std::string> commentsAbove(const std::vector<std::string>& lines, int line) {
  int first = line - 1;  // 1-based index of the line above
  while (first >= 1 && isComment(lines[std::size_t(first - 1)])) --first;
  std::vector<std::string> out;
  for (int l = first + 1; l < line; ++l) out.push_back(commentText(lines[std::size_t(l - 1)]));
  return out;
}

// The comment lines after the item starting at line `line` (its continuation lines, indented
// deeper than it, skipped), up to the next line that is not a comment.
std::vector<std::string> commentsAfter(const std::vector<std::string>& lines, int line) {
  const std::size_t indent = indentOf(lines[std::size_t(line - 1)]);
  std::size_t l = std::size_t(line);  // 0-based index of the next line
  while (l < lines.size() && !isComment(lines[l]) && !isBlank(lines[l]) && indentOf(lines[l]) > indent)
    ++l;
  std::vector<std::string> out;
  while (l < lines.size() && isComment(lines[l])) out.push_back(commentText(lines[l++]));
  return out;
}

void attachComments(ErrorModelSpec& spec, const ConfigNode& root, const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  for (const auto& l : lines) {
    if (isComment(l)) spec.headerComments.push_back(commentText(l));
    else if (!isBlank(l)) break;
  }
  for (Sensor sensor : {Sensor::gyro, Sensor::accel}) {
    ConfigNode sn = root[sensorName(sensor)];
    if (!sn.isMap()) continue;
    for (EffectList l : {EffectList::triad, EffectList::all, EffectList::x, EffectList::y,
                         EffectList::z}) {
      ConfigNode ln = sn[listName(l)];
      auto& effects = spec.sensor(sensor).list(l);
      auto& trailing = spec.sensor(sensor).trailing[int(l)];
      if (!ln.exists() || !ln.isSequence()) continue;
      auto blockItem = [&](int line, char c) {
        return line >= 1 && line <= int(lines.size()) && startsWith(lines[std::size_t(line - 1)], c);
      };
      if (effects.empty()) {
        if (blockItem(ln.line(), '[')) trailing = commentsAbove(lines, ln.line());
        continue;
      }
      for (auto& e : effects)
        if (blockItem(e.where.line, '-')) e.comments = commentsAbove(lines, e.where.line);
      const int last = effects.back().where.line;
      if (blockItem(last, '-')) trailing = commentsAfter(lines, last);
    }
  }
}

ErrorModelSpec readFile(ConfigFile& file, const std::string& text) {
  ConfigNode root = file.root();
  ErrorModelSpec spec = readErrorModel(root);
  file.throwIfErrors();
  if (root.isMap()) attachComments(spec, root, text);
  spec.source = file.name();
  return spec;
}

}  // namespace

ErrorModelSpec loadErrorModel(const std::string& path) {
  // The common loader refuses directories, devices and oversized files, and says what an empty
  // file would mean; the text is read once more for the comments (a file of at most 4 MiB).
  ConfigFile file = ConfigFile::load(
      path, "an empty error model; write `gyro: {}` if you mean a perfect IMU");
  return readFile(file, readRegularFile(path, limits::kMaxYamlBytes, "YAML file"));
}

ErrorModelSpec errorModelFromString(const std::string& text, const std::string& name) {
  ConfigFile file = ConfigFile::fromString(text, name);
  return readFile(file, text);
}

}  // namespace sinsim::errormodels
