// Text the reports share: numbers, channel lists, parameter notes and plot figures.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "io/estimate_text.hpp"
#include "io/report_parts.hpp"
#include "io/svg_plot.hpp"

namespace frictionid {

std::string num(double x) {
  return plain_number(x);
}
std::string num(const std::optional<double>& x) {
  return x ? num(*x) : "—";
}

std::vector<std::string> result_items(const FitResult& r) {
  std::vector<std::string> items;
  for (const auto& p : r.parameters) {
    const bool has_error = !p.fixed && !p.at_bound && p.std_error;
    const EstimateText e = estimate_text(p.value, has_error ? p.std_error : std::nullopt);
    std::string item = p.name + " = " + e.joined();
    if (p.fixed)
      item += " (fixed)";
    else if (p.at_bound)
      item += " (at a bound)";
    else if (!p.std_error)
      item += " (not determined)";
    else if (!e.relative.empty())
      item += " (" + e.relative + ")";
    items.push_back(item);
  }
  return items;
}

std::string provenance_markdown(const Provenance& p) {
  std::string md = "## Traceability\n\n";
  for (const auto& [label, text] : provenance_lines(p)) {
    std::string one_line = text;
    for (char& ch : one_line)
      if (ch == '\n' || ch == '\r') ch = ' ';
    md += "- " + label + ": " + one_line + "\n";
  }
  return md + "\n";
}

const char* channel_unit(Channel c) {
  return (c == Channel::T_x || c == Channel::T_y) ? "newton" : "newton metre";
}

std::string join_channels(const std::vector<Channel>& cs) {
  std::string out;
  for (std::size_t i = 0; i < cs.size(); ++i)
    out += (i ? ", " : "") + std::string(channel_name(cs[i]));
  return out.empty() ? "none" : out;
}

std::string contact_words(const std::string& contact) {
  return contact == "circle" ? std::string() : ", contact " + contact;
}

std::string parameter_note(const ParameterEstimate& p, const char* at_bound,
                           const char* undetermined) {
  std::vector<std::string> notes;
  if (p.fixed) notes.emplace_back("fixed");
  if (p.at_bound) notes.emplace_back(at_bound);
  if (!p.fixed && !p.at_bound && !p.std_error) notes.emplace_back(undetermined);
  std::string out;
  for (std::size_t i = 0; i < notes.size(); ++i) out += (i ? "; " : "") + notes[i];
  return out;
}

std::string plot_figure(const ReportPlot& p) {
  using svg::escape;
  return fmt::format("<figure class=\"plot\" data-file=\"{}\">\n", escape(p.file)) + p.svg +
         fmt::format("\n<figcaption>{} File: <a href=\"{}\">{}</a>.</figcaption>\n</figure>",
                     escape(p.caption), escape(p.file), escape(p.file));
}

}  // namespace frictionid
