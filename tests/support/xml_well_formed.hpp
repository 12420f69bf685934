// A small well-formedness check for the SVG and HTML files frictionid writes, so that tests can
// feed the writers hostile text without a parser library: the whole text must be UTF-8 of
// characters that XML 1.0 allows, every element closed in order, every attribute quoted and
// unique, every '&' an entity or character reference, one root element. In HTML mode a doctype
// is allowed, void elements (meta, br, ...) have no end tag, script and style hold raw text,
// and DEL and the C1 controls are errors too (HTML counts them as parse errors).
#pragma once

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace frictionid::test {

namespace xml_detail {

class Checker {
 public:
  Checker(std::string_view text, bool html) : s_(text), html_(html) {}

  // Empty when the text is well-formed, else what is wrong and at which byte.
  std::string run() {
    if (std::string e = characters(); !e.empty()) return e;
    skip_misc();
    if (starts("<?xml")) {
      if (!skip_past("?>")) return fail("unterminated XML declaration");
      skip_misc();
    }
    if (starts("<!DOCTYPE")) {
      if (!html_) return fail("doctype in an SVG file");
      if (!skip_past(">")) return fail("unterminated doctype");
      skip_misc();
    }
    if (!starts("<")) return fail("no root element");
    if (std::string e = root_element(); !e.empty()) return e;
    skip_misc();
    if (i_ != s_.size()) return fail("text after the root element");
    return "";
  }

 private:
  std::string fail(const std::string& what) const {
    return what + " at byte " + std::to_string(i_) + " near '" +
           std::string(s_.substr(i_ < 20 ? 0 : i_ - 20, 40)) + "'";
  }
  bool starts(std::string_view p) const { return s_.substr(i_, p.size()) == p; }
  bool skip_past(std::string_view end) {
    const std::size_t at = s_.find(end, i_);
    if (at == std::string_view::npos) return false;
    i_ = at + end.size();
    return true;
  }
  void skip_space() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\t' || s_[i_] == '\r'))
      ++i_;
  }
  void skip_misc() {
    for (;;) {
      skip_space();
      if (!starts("<!--") || !skip_past("-->")) return;
    }
  }

  // Every character: UTF-8, allowed by XML 1.0 (and in HTML mode not DEL or a C1 control).
  std::string characters() {
    for (i_ = 0; i_ < s_.size();) {
      const auto b = [&](std::size_t k) {
        return i_ + k < s_.size() ? static_cast<unsigned char>(s_[i_ + k]) : 0u;
      };
      const unsigned lead = b(0);
      std::uint32_t cp = 0;
      std::size_t n = 0;
      if (lead < 0x80) {
        cp = lead, n = 1;
      } else if (lead >= 0xc2 && lead <= 0xdf) {
        cp = lead & 0x1f, n = 2;
      } else if (lead >= 0xe0 && lead <= 0xef) {
        cp = lead & 0x0f, n = 3;
      } else if (lead >= 0xf0 && lead <= 0xf4) {
        cp = lead & 0x07, n = 4;
      } else {
        return fail("a byte that is not UTF-8");
      }
      for (std::size_t k = 1; k < n; ++k) {
        if ((b(k) & 0xc0) != 0x80) return fail("a cut UTF-8 sequence");
        cp = cp << 6 | (b(k) & 0x3f);
      }
      const std::uint32_t least[] = {0, 0, 0x80, 0x800, 0x10000};
      if (cp < least[n] || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff))
        return fail("an overlong, surrogate or out-of-range UTF-8 sequence");
      const bool xml_char = cp == 0x9 || cp == 0xa || cp == 0xd || (cp >= 0x20 && cp <= 0xd7ff) ||
                            (cp >= 0xe000 && cp <= 0xfffd) || cp >= 0x10000;
      if (!xml_char) return fail("a character that XML does not allow (U+" + hex(cp) + ")");
      if (html_ && (cp == 0x7f || (cp >= 0x80 && cp <= 0x9f)))
        return fail("a control character (U+" + hex(cp) + ")");
      i_ += n;
    }
    i_ = 0;
    return "";
  }
  static std::string hex(std::uint32_t cp) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string out;
    for (int shift = 12; shift >= 0; shift -= 4) out += kHex[(cp >> shift) & 15];
    return out;
  }

  static bool name_start(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == ':';
  }
  static bool name_char(char c) {
    return name_start(c) || (c >= '0' && c <= '9') || c == '-' || c == '.';
  }
  std::string name() {
    const std::size_t from = i_;
    if (i_ >= s_.size() || !name_start(s_[i_])) return "";
    while (i_ < s_.size() && name_char(s_[i_])) ++i_;
    return std::string(s_.substr(from, i_ - from));
  }

  // '&' at i_: an entity the writers may use, or a character reference.
  std::string reference() {
    ++i_;
    for (std::string_view e : {"amp;", "lt;", "gt;", "quot;", "apos;"})
      if (starts(e)) {
        i_ += e.size();
        return "";
      }
    if (starts("#x")) {
      i_ += 2;
      const std::size_t from = i_;
      while (i_ < s_.size() && std::isxdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
      if (i_ > from && starts(";")) return ++i_, "";
    } else if (starts("#")) {
      const std::size_t from = ++i_;
      while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
      if (i_ > from && starts(";")) return ++i_, "";
    }
    return fail("an '&' that is not an entity");
  }

  // A start tag at i_ ('<' then a name); sets `empty` for "/>".
  std::string start_tag(std::string& tag, bool& empty) {
    ++i_;
    tag = name();
    if (tag.empty()) return fail("a '<' that starts no tag");
    std::set<std::string> seen;
    for (;;) {
      const std::size_t before = i_;
      skip_space();
      if (starts("/>")) return i_ += 2, empty = true, "";
      if (starts(">")) return ++i_, empty = false, "";
      if (i_ == before) return fail("no space before an attribute");
      const std::string attribute = name();
      if (attribute.empty()) return fail("a bad attribute name in <" + tag + ">");
      if (!seen.insert(attribute).second) return fail("attribute " + attribute + " twice");
      skip_space();
      if (html_ && !starts("=")) continue;  // a boolean attribute such as <details open>
      if (!starts("=")) return fail("attribute " + attribute + " without a value");
      ++i_;
      skip_space();
      if (!starts("\"") && !starts("'")) return fail("attribute " + attribute + " not quoted");
      const char quote = s_[i_++];
      while (i_ < s_.size() && s_[i_] != quote) {
        if (s_[i_] == '<') return fail("a '<' in attribute " + attribute);
        if (s_[i_] == '&') {
          if (std::string e = reference(); !e.empty()) return e;
        } else {
          ++i_;
        }
      }
      if (i_ >= s_.size()) return fail("unterminated attribute " + attribute);
      ++i_;
    }
  }

  bool is_void(const std::string& tag) const {
    static const std::set<std::string> kVoid = {"area",   "base",  "br",    "col",  "embed",
                                                "hr",     "img",   "input", "link", "meta",
                                                "source", "track", "wbr"};
    return html_ && kVoid.count(tag) > 0;
  }

  // Markup from the root's start tag at i_ to the end tag that closes it.
  std::string root_element() {
    std::vector<std::string> open;
    do {
      if (starts("<!--")) {
        if (!skip_past("-->")) return fail("unterminated comment");
      } else if (starts("</")) {
        i_ += 2;
        const std::string tag = name();
        skip_space();
        if (!starts(">")) return fail("a bad end tag");
        ++i_;
        if (open.empty() || open.back() != tag)
          return fail("</" + tag + "> closes " +
                      (open.empty() ? "nothing" : "<" + open.back() + ">"));
        open.pop_back();
      } else if (starts("<")) {
        std::string tag;
        bool empty = false;
        if (std::string e = start_tag(tag, empty); !e.empty()) return e;
        if (empty || is_void(tag)) continue;
        if (html_ && (tag == "script" || tag == "style")) {
          if (!skip_past("</" + tag + ">")) return fail("unterminated <" + tag + ">");
          continue;
        }
        open.push_back(tag);
      } else if (s_[i_] == '&') {
        if (std::string e = reference(); !e.empty()) return e;
      } else if (s_[i_] == '>' && !html_ && i_ >= 2 && s_.substr(i_ - 2, 3) == "]]>") {
        return fail("']]>' in text");
      } else {
        ++i_;
      }
    } while (!open.empty() && i_ < s_.size());
    if (!open.empty()) return fail("<" + open.back() + "> is never closed");
    return "";
  }

  std::string_view s_;
  bool html_;
  std::size_t i_ = 0;
};

}  // namespace xml_detail

// Empty when `text` is a well-formed XML document (an SVG file), else the first problem.
inline std::string xml_problem(std::string_view text) {
  return xml_detail::Checker(text, /*html=*/false).run();
}

// Empty when `text` is an HTML page of the shape frictionid writes that is well-formed in the
// sense above, else the first problem.
inline std::string html_problem(std::string_view text) {
  return xml_detail::Checker(text, /*html=*/true).run();
}

}  // namespace frictionid::test
