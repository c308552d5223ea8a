// SPDX-License-Identifier: MIT
// ddfcam: a minimal XML element scanner for VTK XML files (no DTD, no namespaces).
#include "vtk_xml_document.h"

#include <ddfcam/error.h>

#include <cctype>

namespace ddfcam::io::detail {
namespace {

constexpr std::size_t kMaxDepth = 64;
constexpr std::size_t kMaxElements = 1'000'000;

bool isNameChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == ':' ||
         c == '.';
}

std::string decodeEntities(std::string_view raw) {
  std::string out;
  out.reserve(raw.size());
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] != '&') {
      out += raw[i];
      continue;
    }
    static constexpr std::pair<std::string_view, char> kEntities[] = {
        {"&lt;", '<'}, {"&gt;", '>'}, {"&amp;", '&'}, {"&quot;", '"'}, {"&apos;", '\''}};
    bool matched = false;
    for (const auto& [entity, c] : kEntities) {
      if (raw.substr(i, entity.size()) == entity) {
        out += c;
        i += entity.size() - 1;
        matched = true;
        break;
      }
    }
    if (!matched) out += '&';
  }
  return out;
}

class Scanner {
 public:
  Scanner(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  XmlDocument run() {
    std::vector<int> stack;
    while (true) {
      const std::size_t lt = text_.find('<', pos_);
      if (lt == std::string_view::npos) break;
      pos_ = lt;
      if (startsWith("<?")) {
        skipPast("?>");
      } else if (startsWith("<!--")) {
        skipPast("-->");
      } else if (startsWith("<!")) {
        skipPast(">");
      } else if (startsWith("</")) {
        closeTag(stack);
      } else if (openTag(stack)) {
        break;  // AppendedData: the rest is data
      }
    }
    if (doc_.elements.empty()) fail("no XML element");
    if (!stack.empty() && !doc_.appendedStart)
      fail("element <" + doc_.elements[stack.back()].name + "> is not closed");
    return std::move(doc_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw IoError(source_ + ": " + what + " (XML offset " + std::to_string(pos_) + ")");
  }
  bool startsWith(std::string_view s) const { return text_.substr(pos_, s.size()) == s; }
  void skipPast(std::string_view end) {
    const std::size_t at = text_.find(end, pos_);
    if (at == std::string_view::npos) fail("unterminated markup");
    pos_ = at + end.size();
  }
  void skipSpace() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  std::string readName() {
    const std::size_t begin = pos_;
    while (pos_ < text_.size() && isNameChar(text_[pos_])) ++pos_;
    if (pos_ == begin) fail("expected a name");
    return std::string(text_.substr(begin, pos_ - begin));
  }

  void closeTag(std::vector<int>& stack) {
    const std::size_t lt = pos_;
    pos_ += 2;
    const std::string name = readName();
    skipSpace();
    if (pos_ >= text_.size() || text_[pos_] != '>') fail("malformed closing tag </" + name + ">");
    if (stack.empty() || doc_.elements[stack.back()].name != name)
      fail("unexpected closing tag </" + name + ">");
    doc_.elements[stack.back()].contentEnd = lt;
    ++pos_;
    stack.pop_back();
  }

  void readAttributes(XmlElement& e) {
    while (true) {
      skipSpace();
      if (pos_ >= text_.size()) fail("unterminated tag <" + e.name + ">");
      if (text_[pos_] == '>' || text_[pos_] == '/') return;
      std::string key = readName();
      skipSpace();
      if (pos_ >= text_.size() || text_[pos_] != '=') fail("attribute " + key + " has no value");
      ++pos_;
      skipSpace();
      if (pos_ >= text_.size() || (text_[pos_] != '"' && text_[pos_] != '\''))
        fail("attribute " + key + " is not quoted");
      const char quote = text_[pos_++];
      const std::size_t end = text_.find(quote, pos_);
      if (end == std::string_view::npos) fail("unterminated attribute " + key);
      e.attributes.emplace_back(std::move(key), decodeEntities(text_.substr(pos_, end - pos_)));
      pos_ = end + 1;
    }
  }

  // Returns true when the element is AppendedData (scanning stops).
  bool openTag(std::vector<int>& stack) {
    XmlElement e;
    e.tagBegin = pos_;
    ++pos_;
    e.name = readName();
    readAttributes(e);
    const bool selfClosing = text_[pos_] == '/';
    if (selfClosing && (pos_ + 1 >= text_.size() || text_[pos_ + 1] != '>'))
      fail("malformed tag <" + e.name + ">");
    pos_ += selfClosing ? 2 : 1;
    if (doc_.elements.size() >= kMaxElements) fail("too many XML elements");
    if (!doc_.elements.empty() && stack.empty()) fail("more than one root element");
    const int index = static_cast<int>(doc_.elements.size());
    e.parent = stack.empty() ? -1 : stack.back();
    e.contentBegin = e.contentEnd = pos_;
    if (e.parent >= 0) doc_.elements[e.parent].children.push_back(index);
    const bool appended = e.name == "AppendedData";
    doc_.elements.push_back(std::move(e));
    if (appended && !selfClosing) {
      const std::size_t underscore = text_.find('_', pos_);
      if (underscore == std::string_view::npos) fail("AppendedData has no '_' marker");
      doc_.appendedStart = underscore + 1;
      doc_.appendedElement = index;
      return true;
    }
    if (!selfClosing) {
      if (stack.size() >= kMaxDepth) fail("XML nested too deeply");
      stack.push_back(index);
    }
    return false;
  }

  std::string_view text_;
  const std::string& source_;
  std::size_t pos_ = 0;
  XmlDocument doc_;
};

}  // namespace

std::optional<std::string> XmlElement::attribute(std::string_view key) const {
  for (const auto& [k, v] : attributes)
    if (k == key) return v;
  return std::nullopt;
}

std::vector<int> XmlDocument::children(int parent, std::string_view name) const {
  std::vector<int> out;
  for (const int c : elements[parent].children)
    if (elements[c].name == name) out.push_back(c);
  return out;
}

std::optional<int> XmlDocument::child(int parent, std::string_view name) const {
  for (const int c : elements[parent].children)
    if (elements[c].name == name) return c;
  return std::nullopt;
}

XmlDocument parseXml(std::string_view text, const std::string& source) {
  return Scanner(text, source).run();
}

}  // namespace ddfcam::io::detail
