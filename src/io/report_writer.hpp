// Turns a FitResult into files: report.json (design.md "report.json"), report.md and gnuplot SVG
// plots. Output is a pure function of the FitResult (and Dataset for plots): no timestamps, no
// wall times, no absolute paths, so the same input and seed give byte-identical reports.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "identify/dataset.hpp"
#include "identify/fit_result.hpp"
#include "io/gnuplot.hpp"

namespace frictionid {

// The report as JSON, keys in design.md's order, parameters in FitResult order. Absent optionals
// and non-finite doubles are null (an infinite bound, i.e. unbounded, is null too).
nlohmann::ordered_json report_json(const FitResult& r);

// Human-readable Markdown report. This overload links the plots write_report would produce for
// every fitted channel (fit_<channel>.svg, residuals_<channel>.svg).
std::string report_markdown(const FitResult& r);

// Same, linking exactly `plot_files` (file names relative to the report directory); with an
// empty list the Plots section says that no plots were produced.
std::string report_markdown(const FitResult& r, const std::vector<std::string>& plot_files);

// Writes DIR/report.json, DIR/report.md and, when gnuplot works, DIR/fit_<c>.svg and
// DIR/residuals_<c>.svg for each fitted channel c; creates DIR if needed. Every file is written
// atomically. A missing or failing gnuplot only drops the plots (and report.md then links none).
// Returns the paths written (DIR joined with the file name): report.json, report.md, then plots.
// Throws std::runtime_error when DIR cannot be created or a report file cannot be written.
std::vector<std::string> write_report(const std::string& dir, const FitResult& r, const Dataset& d);

}  // namespace frictionid
