// Runs gnuplot to make SVG plots: one run in a private temporary directory (so the output
// directory's path, quotes or spaces, never enters a script, and a failing gnuplot leaves nothing
// behind), then every SVG is copied into place with write_file_atomically.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace frictionid {

// True when a `gnuplot` executable is on PATH.
bool gnuplot_available();

// `prepare` writes its data files into the work directory, appends plot commands to the script
// (which already sets the SVG terminal; file names relative to the work directory) and returns
// the SVG names it expects. Returns the names actually written into `dir`; never throws for a
// missing or failing gnuplot (plots are optional).
using PlotPreparer =
    std::function<std::vector<std::string>(const std::filesystem::path& work, std::string& script)>;
std::vector<std::string> render_svgs(const std::filesystem::path& dir, const PlotPreparer& prepare);

// Quotes a string for gnuplot's single-quoted strings and the shell alike.
std::string shell_quote(const std::string& s);

}  // namespace frictionid
