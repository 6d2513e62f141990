// A small XML well-formedness checker (XML 1.0 §2.1, §3.1, §4.1 subset): one root element,
// properly nested and matching tags, quoted attribute values without '<', unique attribute names
// per element, and '&' only in the predefined or numeric character references. Enough to catch
// an unescaped label or an unclosed element in generated SVG; no DTDs, no CDATA.
#pragma once

#include <cctype>
#include <set>
#include <string>
#include <vector>

namespace sinsim::report::testing {

/// Empty when `doc` is well-formed, else the first problem with its byte offset.
inline std::string xmlProblem(const std::string& doc) {
  std::size_t i = 0;
  std::vector<std::string> stack;
  int roots = 0;
  auto fail = [&](const std::string& what) { return what + " at byte " + std::to_string(i); };
  auto isNameChar = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == ':' ||
           c == '.';
  };
  auto entityOk = [&](std::size_t at) {  // doc[at] == '&'
    static const char* named[] = {"amp;", "lt;", "gt;", "quot;", "apos;"};
    for (const char* n : named)
      if (doc.compare(at + 1, std::string(n).size(), n) == 0) return true;
    std::size_t j = at + 1;
    if (j >= doc.size() || doc[j] != '#') return false;
    ++j;
    const bool hex = j < doc.size() && doc[j] == 'x';
    if (hex) ++j;
    const std::size_t start = j;
    while (j < doc.size() && (hex ? std::isxdigit(static_cast<unsigned char>(doc[j]))
                                  : std::isdigit(static_cast<unsigned char>(doc[j]))))
      ++j;
    return j > start && j < doc.size() && doc[j] == ';';
  };
  auto readName = [&]() {
    const std::size_t s = i;
    while (i < doc.size() && isNameChar(doc[i])) ++i;
    return doc.substr(s, i - s);
  };
  auto skipSpace = [&]() {
    while (i < doc.size() && std::isspace(static_cast<unsigned char>(doc[i]))) ++i;
  };

  while (i < doc.size()) {
    const char c = doc[i];
    if (c == '&') {
      if (!entityOk(i)) return fail("bare '&' in text");
      ++i;
      continue;
    }
    if (c != '<') {
      if (stack.empty() && !std::isspace(static_cast<unsigned char>(c)))
        return fail("text outside the root element");
      ++i;
      continue;
    }
    if (doc.compare(i, 4, "<!--") == 0) {
      const std::size_t e = doc.find("-->", i + 4);
      if (e == std::string::npos) return fail("unterminated comment");
      i = e + 3;
      continue;
    }
    if (doc.compare(i, 2, "<?") == 0) {
      const std::size_t e = doc.find("?>", i + 2);
      if (e == std::string::npos) return fail("unterminated processing instruction");
      i = e + 2;
      continue;
    }
    if (doc.compare(i, 2, "</") == 0) {
      i += 2;
      const std::string name = readName();
      skipSpace();
      if (i >= doc.size() || doc[i] != '>') return fail("malformed end tag </" + name);
      ++i;
      if (stack.empty() || stack.back() != name)
        return fail("end tag </" + name + "> does not match <" +
                    (stack.empty() ? std::string("(none)") : stack.back()) + ">");
      stack.pop_back();
      continue;
    }
    ++i;
    const std::string name = readName();
    if (name.empty()) return fail("'<' not starting a tag");
    if (stack.empty() && ++roots > 1) return fail("second root element <" + name + ">");
    std::set<std::string> attrs;
    for (;;) {
      const std::size_t before = i;
      skipSpace();
      if (i >= doc.size()) return fail("unterminated tag <" + name);
      if (doc[i] == '>') {
        ++i;
        stack.push_back(name);
        break;
      }
      if (doc.compare(i, 2, "/>") == 0) {
        i += 2;
        break;
      }
      if (i == before) return fail("missing space before attribute in <" + name);
      const std::string attr = readName();
      if (attr.empty()) return fail("bad character in tag <" + name);
      if (!attrs.insert(attr).second) return fail("duplicate attribute " + attr);
      skipSpace();
      if (i >= doc.size() || doc[i] != '=') return fail("attribute " + attr + " without '='");
      ++i;
      skipSpace();
      if (i >= doc.size() || (doc[i] != '"' && doc[i] != '\'')) return fail("unquoted " + attr);
      const char q = doc[i++];
      while (i < doc.size() && doc[i] != q) {
        if (doc[i] == '<') return fail("'<' in attribute " + attr);
        if (doc[i] == '&' && !entityOk(i)) return fail("bare '&' in attribute " + attr);
        ++i;
      }
      if (i >= doc.size()) return fail("unterminated attribute " + attr);
      ++i;
    }
  }
  if (!stack.empty()) return "unclosed element <" + stack.back() + "> at end";
  if (roots != 1) return "no root element";
  return "";
}

}  // namespace sinsim::report::testing
