// write_report: one transaction (io/report_transaction.hpp) around report.json, report.md,
// report.html and every plot as an SVG file.
#include <frictionid/io/report_writer.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "io/report_parts.hpp"
#include "io/report_transaction.hpp"
#include "io/svg_plot.hpp"

namespace frictionid {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;

std::string report_html(const FitResult& r, const Dataset& d, const ReportOptions& o) {
  return report_html_page(r, make_plots(r, d, o), o.provenance, o.contact);
}

std::vector<std::string> write_report_files(const fs::path& dir, const FitResult& r,
                                            const Dataset& d, const ReportOptions& o) {
  const std::vector<ReportPlot> plots = make_plots(r, d, o);
  std::vector<std::string> written;
  const std::string json =
      report_json(r, o.provenance, o.contact).dump(2, ' ', false, ojson::error_handler_t::replace);
  write_staged_file(dir / "report.json", json + "\n");
  written.push_back("report.json");
  std::vector<std::string> plot_files;
  for (const auto& p : plots) plot_files.push_back(p.file);
  write_staged_pages(dir, "report", report_markdown(r, plot_files, o.provenance, o.contact),
                     report_html_page(r, plots, o.provenance, o.contact), plots, written);
  return written;
}

void write_staged_pages(const fs::path& dir, const std::string& stem, const std::string& markdown,
                        const std::string& html, const std::vector<ReportPlot>& plots,
                        std::vector<std::string>& names) {
  write_staged_file(dir / (stem + ".md"), markdown);
  names.push_back(stem + ".md");
  write_staged_file(dir / (stem + ".html"), html);
  names.push_back(stem + ".html");
  for (const auto& p : plots) {
    write_staged_file(dir / p.file, svg::standalone_file(p.svg));
    names.push_back(p.file);
  }
}

std::vector<std::string> write_report(const std::string& dir, const FitResult& r, const Dataset& d,
                                      const ReportOptions& o) {
  check_report_columns(d, o);  // a column the options name but the data lack: before any I/O
  ReportTransaction transaction(dir, o.stop);
  const std::vector<std::string> names = write_report_files(transaction.staging(), r, d, o);
  transaction.commit();
  std::vector<std::string> written;
  for (const auto& n : names) written.push_back((fs::path(dir) / n).string());
  return written;
}

}  // namespace frictionid
