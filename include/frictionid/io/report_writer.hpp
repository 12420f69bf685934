// Turns a FitResult into files: report.json (docs/design.md "report.json"), report.md, report.html
// and SVG plots. Output is a pure function of the FitResult (and Dataset for plots): no timestamps,
// no wall times, no absolute paths, so the same input and seed give byte-identical reports.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <frictionid/dataset.hpp>
#include <frictionid/fit_result.hpp>
#include <frictionid/io/provenance.hpp>

namespace frictionid {

// What the plots show beyond the defaults (the fit command's --plot-x and --color-by).
struct ReportOptions {
  std::vector<std::string> plot_x;  // columns to plot every fitted channel against
  std::string color_by;             // colours of the collapse plots; empty: the load N, when it
                                    // takes at most 8 values
  int threads = 0;                  // threads drawing the plots (a channel each); 0: all cores
  Provenance provenance;            // printed on every page and in report.json
  // The contact spot as --contact spells it (contact_spot_label of pressure_map_reader.hpp);
  // stated in every file of the report unless it is the circle, whose reports stay as they were.
  std::string contact = "circle";
  // Asked while waiting for the report directory's lock and before the swap: true ends the
  // report with Interrupted (src/io/stop_check.hpp), the earlier report intact. The command
  // line's reads its signal flag.
  std::function<bool()> stop;
};

// The report as JSON, keys in docs/design.md's order, parameters in FitResult order. Absent
// optionals and non-finite doubles are null (an infinite bound, i.e. unbounded, is null too).
// `contact` (ReportOptions::contact) follows "pressure" as the key "contact" unless it is
// "circle".
nlohmann::ordered_json report_json(const FitResult& r, const std::string& contact = "circle");
// The same with a last key "provenance" (io/provenance.hpp): what write_report writes.
nlohmann::ordered_json report_json(const FitResult& r, const Provenance& p,
                                   const std::string& contact = "circle");

// Human-readable Markdown report. This overload links the plots write_report would produce for
// every fitted channel (collapse_<channel>.svg, fit_<channel>.svg, residuals_<channel>.svg).
std::string report_markdown(const FitResult& r);

// Same, linking exactly `plot_files` (file names relative to the report directory); with an
// empty list the Plots section says that no plots were produced.
std::string report_markdown(const FitResult& r, const std::vector<std::string>& plot_files,
                            const Provenance& p = {}, const std::string& contact = "circle");

// Throws std::invalid_argument naming the option when a column in `o` is not in the dataset
// (canonical columns, eps, channels or the file's extra columns) or a --plot-x column holds text.
void check_report_columns(const Dataset& d, const ReportOptions& o);

// report.html: one self-contained page (inline SVG plots, inline style and a small sorting
// script, no external request) with the warnings, parameters, correlation heat map, plots per
// channel incl. the collapse plot, statistics, global search and solver, and a glossary.
// Throws std::invalid_argument for a column in `o` that the dataset lacks.
std::string report_html(const FitResult& r, const Dataset& d, const ReportOptions& o = {});

// Writes DIR/report.json, DIR/report.md, DIR/report.html and the plots as SVG files
// (collapse_<c>.svg, fit_<c>.svg, residuals_<c>.svg for each fitted channel c, then
// x_<column>_<c>.svg for each --plot-x column); creates DIR if needed. Every file is written
// atomically. Returns the paths written (DIR joined with the file name): report.json, report.md,
// report.html, then the plots. Throws std::runtime_error when DIR cannot be created or a report
// file cannot be written, std::invalid_argument for a column in `o` that the dataset lacks.
std::vector<std::string> write_report(const std::string& dir, const FitResult& r, const Dataset& d,
                                      const ReportOptions& o = {});

}  // namespace frictionid
