// A report file's text without what names the run that wrote it (io/provenance.hpp): the
// "Traceability" section of a page, the "provenance" key of a JSON report. Two runs that differ
// only in how they were asked for (another --jobs, another spelling of the same rows) must give
// the same bytes apart from that.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace frictionid::test {

inline std::string without_traceability(const std::string& text) {
  std::string out = text;
  const auto html = out.find("<h2 id=\"traceability\">");
  if (html != std::string::npos) {
    const auto end = out.find("</dl>\n", html);
    if (end != std::string::npos) out.erase(html, end + 6 - html);
    return out;
  }
  const auto md = out.find("## Traceability\n");
  if (md != std::string::npos) {
    const auto end = out.find("\n\n", md + 16);
    if (end != std::string::npos) out.erase(md, end + 2 - md);
    return out;
  }
  if (!out.empty() && out.front() == '{') {
    auto j = nlohmann::ordered_json::parse(out, nullptr, /*allow_exceptions=*/false);
    if (!j.is_discarded() && j.is_object() && j.contains("provenance")) {
      j.erase("provenance");
      return j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
    }
  }
  return out;
}

}  // namespace frictionid::test
