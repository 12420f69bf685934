// A small SVG plot writer for the reports: dots and lines over linear or logarithmic axes, with
// ticks, grid, legend and dashed markers. Output is a pure function of the Plot (fixed number
// formatting, no ids, no clock), so the same plot is the same bytes.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace frictionid::svg {

enum class Mark { Dots, Line };

struct Series {
  Series() = default;
  Series(std::string label_, std::string color_, Mark mark_, std::vector<double> x_ = {},
         std::vector<double> y_ = {})
      : label(std::move(label_)),
        color(std::move(color_)),
        mark(mark_),
        x(std::move(x_)),
        y(std::move(y_)) {}

  std::string label;  // legend text; empty keeps the series out of the legend
  std::string color;  // CSS colour, e.g. "#0072b2" (io/palette.hpp)
  Mark mark = Mark::Dots;
  std::vector<double> x, y;  // a pair that is not finite (or <= 0 on a log axis) is skipped
  // Written as the data-tag attribute of the series' path (when not empty): which group or
  // curve it draws, for a reader of the SVG.
  std::string tag;
  bool outline = false;   // a line drawn over a white halo, so that it shows over dots
  std::string dash;       // a line's stroke-dasharray, e.g. "6 3"; empty: solid
  double dot_size = 3.4;  // a dot's diameter in pixels
  double opacity = 0.75;  // of the dots
};

// A dashed vertical line at x with a label at its top, e.g. the edge where eps = 0 rows sit.
struct XMarker {
  double x = 0.0;
  std::string label;
};

struct Plot {
  std::string title;
  std::vector<std::string> notes;  // smaller lines under the title
  std::string x_label, y_label;
  bool log_x = false, log_y = false;
  std::optional<std::pair<double, double>> x_range;  // default: the data's range
  std::optional<double> y_reference;                 // dashed horizontal line, e.g. 0
  std::vector<XMarker> x_markers;
  std::vector<Series> series;
  // The size in pixels (the viewBox). The title and notes are wrapped to the width; the height
  // grows where they and the legend would leave the axes less than 200 px. 440 px wide with
  // 11 px text: three plots side by side on a 1400 px screen show the text at about 10 px.
  int width = 440, height = 380;
};

// The plot as an <svg> element without a namespace attribute (for inline use in HTML). The
// element is accessible as an image: role="img", aria-label="description(p)", and a <title>
// with the plot's title as its first child.
std::string render(const Plot& p);

// The plot in words, for its aria-label: the title, what is drawn against what (and a log
// axis), the legend's series and the notes, e.g. "T_x: collapse, T_x / N against eps. T_x / N
// (parity sign removed) against eps = v/(|omega| R) (log scale). Series: N = 2000, N = 4000.
// colour: N." Plain text (not escaped).
std::string description(const Plot& p);

// An <svg> element from render() as a standalone .svg file (XML declaration and namespace).
std::string standalone_file(const std::string& svg_element);

// Tick positions: 1, 2, 5 times a power of ten covering [lo, hi] with about `target` ticks.
std::vector<double> linear_ticks(double lo, double hi, int target = 6);
// Decades covering [lo, hi] (lo > 0), with 2 and 5 in between when there are fewer than three.
std::vector<double> log_ticks(double lo, double hi);
// A tick label: up to 4 significant digits, no trailing zeros ("0.01", "250", "1e+06").
std::string tick_label(double v);
// Text escaped for XML and HTML content and attribute values; whatever the bytes, the result is
// well-formed XML text: a control character other than tab, LF and CR, DEL, a C1 control, the
// non-characters U+FFFE and U+FFFF and every byte that is not UTF-8 are shown as the text \xNN.
std::string escape(const std::string& s);

}  // namespace frictionid::svg
