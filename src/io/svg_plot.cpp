#include "io/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

#include <fmt/format.h>

#include "io/text.hpp"

namespace frictionid::svg {
namespace {

constexpr double kLeft = 74, kRight = 18, kTitleLine = 22, kNoteLine = 15;
constexpr double kLegendRow = 18, kBelowAxis = 44;
constexpr double kCharWidth = 6.6;        // average width of an 11 px sans-serif character
constexpr double kLegendCharWidth = 6.2;  // of a legend's (labels are short, digits and words)
constexpr double kTitleCharWidth = 8.4;   // of a 14 px bold one
constexpr double kTitleRow = 17;          // a wrapped title's line spacing
constexpr double kMinAxesHeight = 200;    // the plot grows taller rather than squeeze its axes

// Characters of UTF-8 text (its bytes that do not continue a sequence).
std::size_t characters(const std::string& s) {
  std::size_t n = 0;
  for (char c : s) n += (static_cast<unsigned char>(c) & 0xc0) != 0x80;
  return n;
}

// Text in lines of at most `width` pixels at `char_width` per character, broken at spaces (a
// longer word keeps a line of its own).
std::vector<std::string> wrap(const std::string& text, double width, double char_width) {
  const auto most = static_cast<std::size_t>(std::max(8.0, width / char_width));
  std::vector<std::string> lines;
  std::string line;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    if (!line.empty() && characters(line) + 1 + characters(word) > most) {
      lines.push_back(line);
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    start = end + 1;
  }
  if (!line.empty() || lines.empty()) lines.push_back(line);
  return lines;
}

// Where the parts of a plot go: the title and notes wrapped to the width, and the height, which
// is the plot's or more, so that the axes keep at least kMinAxesHeight.
struct Frame {
  double W = 0, H = 0;
  std::vector<std::string> title, notes;  // lines
  double top = 0, bottom = 0;             // of the axes: their distance from the edges
};

// Pixel coordinates with one decimal: enough for a 3 px dot, and byte-stable. Written by hand:
// a report draws some 10^5 coordinates, and this is several times faster than fmt here.
void append_px(std::string& out, double v) {
  if (!(std::abs(v) < 1e9)) v = 0;  // only an overflowing range gets here; never print "nan"
  long long tenths = std::llround(v * 10);
  if (tenths < 0) out += '-', tenths = -tenths;
  char digits[24];
  int n = 0;
  for (long long whole = tenths / 10; n == 0 || whole > 0; whole /= 10)
    digits[n++] = static_cast<char>('0' + whole % 10);
  while (n > 0) out += digits[--n];
  out += '.';
  out += static_cast<char>('0' + tenths % 10);
}
std::string px(double v) {
  std::string out;
  append_px(out, v);
  return out;
}

struct Axis {
  bool log = false;
  double lo = 0, hi = 1;    // data units
  double from = 0, to = 1;  // pixels
  double f(double v) const { return log ? std::log10(v) : v; }
  double map(double v) const { return from + (f(v) - f(lo)) / (f(hi) - f(lo)) * (to - from); }
  bool accepts(double v) const { return std::isfinite(v) && (!log || v > 0); }
  bool inside(double v) const { return accepts(v) && v >= lo && v <= hi; }
};

// The range of the accepted values, widened by `pad` of its span on each side (in log units on a
// log axis); a single value or no value still gives a non-empty range.
std::pair<double, double> padded_range(std::vector<double> values, bool log, double pad) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double v : values)
    if (std::isfinite(v) && (!log || v > 0)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!(lo <= hi)) return log ? std::make_pair(1.0, 10.0) : std::make_pair(0.0, 1.0);
  if (log) {
    double a = std::log10(lo), b = std::log10(hi);
    if (b - a < 1e-9) a -= 0.5, b += 0.5;
    const double m = (b - a) * pad;
    return {std::pow(10.0, a - m), std::pow(10.0, b + m)};
  }
  if (hi - lo <= 1e-12 * std::max(std::abs(lo), std::abs(hi))) {
    const double half = lo == 0 ? 1.0 : std::abs(lo) * 0.1;
    lo -= half, hi += half;
  }
  const double m = (hi - lo) * pad;
  return {lo - m, hi + m};
}

struct LegendItem {
  const Series* series;
  double x, y;
};

// Legend layout: items left to right, wrapping into rows below the axes.
std::vector<LegendItem> legend_layout(const Plot& p) {
  std::vector<LegendItem> legend;
  const double usable = p.width - kLeft - kRight;
  double x = 0, row = 0;
  for (const auto& s : p.series) {
    if (s.label.empty()) continue;
    const double w = 26 + kLegendCharWidth * static_cast<double>(characters(s.label)) + 10;
    if (x > 0 && x + w > usable) x = 0, ++row;
    legend.push_back({&s, x, row});
    x += w;
  }
  return legend;
}

// The data ranges of both axes: every series, the x markers (unless x_range is given) and the
// y reference line.
void set_ranges(const Plot& p, Axis& ax, Axis& ay) {
  std::vector<double> xs, ys;
  for (const auto& s : p.series) {
    xs.insert(xs.end(), s.x.begin(), s.x.end());
    ys.insert(ys.end(), s.y.begin(), s.y.end());
  }
  if (p.x_range) {
    std::tie(ax.lo, ax.hi) = *p.x_range;
  } else {
    for (const auto& m : p.x_markers) xs.push_back(m.x);
    std::tie(ax.lo, ax.hi) = padded_range(std::move(xs), ax.log, 0.03);
  }
  if (p.y_reference) ys.push_back(*p.y_reference);
  std::tie(ay.lo, ay.hi) = padded_range(std::move(ys), ay.log, 0.06);
}

}  // namespace

std::string description(const Plot& p) {
  std::string d = p.title.empty() ? std::string("Plot") : p.title;
  if (!p.y_label.empty() || !p.x_label.empty())
    d += ". " + (p.y_label.empty() ? std::string("values") : p.y_label) + " against " +
         (p.x_label.empty() ? std::string("x") : p.x_label) + (p.log_x ? " (log scale)" : "");
  std::vector<std::string> labels;
  for (const auto& s : p.series)
    if (!s.label.empty() && std::find(labels.begin(), labels.end(), s.label) == labels.end())
      labels.push_back(s.label);
  for (std::size_t i = 0; i < labels.size(); ++i) d += (i ? ", " : ". Series: ") + labels[i];
  for (const auto& note : p.notes) d += ". " + note;
  return d + ".";
}

namespace {

// The <svg> start tag (an image to assistive technology, named by its aria-label and its
// <title>, the first child), background, title and notes.
void append_header(std::string& o, const Plot& p, const Frame& f) {
  o += fmt::format(
      "<svg viewBox=\"0 0 {0} {1}\" width=\"{0}\" height=\"{1}\" role=\"img\" "
      "aria-label=\"{2}\" font-family=\"sans-serif\" font-size=\"11\">\n<title>{3}</title>\n"
      "<rect width=\"{0}\" height=\"{1}\" fill=\"#ffffff\"/>\n",
      f.W, f.H, escape(description(p)), escape(p.title.empty() ? description(p) : p.title));
  for (std::size_t i = 0; i < f.title.size(); ++i)
    o += fmt::format(
        "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" font-size=\"14\" "
        "font-weight=\"bold\">{}</text>\n",
        px(f.W / 2), px(17 + kTitleRow * static_cast<double>(i)), escape(f.title[i]));
  const double notes_from = kTitleLine + kTitleRow * static_cast<double>(f.title.size() - 1) + 12;
  for (std::size_t i = 0; i < f.notes.size(); ++i)
    o += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" fill=\"#555555\">{}</text>\n",
                     px(f.W / 2), px(notes_from + kNoteLine * static_cast<double>(i)),
                     escape(f.notes[i]));
}

// Grid, tick labels, the frame and the axis labels.
void append_axes(std::string& o, const Plot& p, const Axis& ax, const Axis& ay) {
  const auto xt = ax.log ? log_ticks(ax.lo, ax.hi) : linear_ticks(ax.lo, ax.hi, 7);
  const auto yt = ay.log ? log_ticks(ay.lo, ay.hi) : linear_ticks(ay.lo, ay.hi, 6);
  o += "<g stroke=\"#e3e3e3\" stroke-width=\"1\">\n";
  for (double t : xt)
    o += fmt::format("<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\"/>\n", px(ax.map(t)),
                     px(ay.from), px(ay.to));
  for (double t : yt)
    o += fmt::format("<line x1=\"{1}\" y1=\"{0}\" x2=\"{2}\" y2=\"{0}\"/>\n", px(ay.map(t)),
                     px(ax.from), px(ax.to));
  o += "</g>\n<g fill=\"#333333\">\n";
  for (double t : xt)
    o += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", px(ax.map(t)),
                     px(ay.from + 15), tick_label(t));
  for (double t : yt)
    o += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>\n", px(ax.from - 5),
                     px(ay.map(t) + 4), tick_label(t));
  o += "</g>\n";
  o += fmt::format(
      "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#888888\"/>\n",
      px(ax.from), px(ay.to), px(ax.to - ax.from), px(ay.from - ay.to));
  o += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" font-size=\"12\">{}</text>\n",
                   px((ax.from + ax.to) / 2), px(ay.from + 33), escape(p.x_label));
  o += fmt::format(
      "<text transform=\"translate(16 {}) rotate(-90)\" text-anchor=\"middle\" "
      "font-size=\"12\">{}</text>\n",
      px((ay.from + ay.to) / 2), escape(p.y_label));
}

// The dashed y reference line and x markers that fall inside the axes.
void append_markers(std::string& o, const Plot& p, const Axis& ax, const Axis& ay) {
  if (p.y_reference && ay.inside(*p.y_reference))
    o += fmt::format(
        "<line x1=\"{1}\" y1=\"{0}\" x2=\"{2}\" y2=\"{0}\" stroke=\"#777777\" "
        "stroke-dasharray=\"5 4\"/>\n",
        px(ay.map(*p.y_reference)), px(ax.from), px(ax.to));
  for (const auto& m : p.x_markers) {
    if (!ax.inside(m.x)) continue;
    const std::string x = px(ax.map(m.x));
    o += fmt::format(
        "<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"#999999\" "
        "stroke-dasharray=\"3 3\"/>\n<text x=\"{0}\" y=\"{3}\" text-anchor=\"middle\" "
        "fill=\"#555555\">{4}</text>\n",
        x, px(ay.from), px(ay.to), px(ay.to - 3), escape(m.label));
  }
}

// The series' data-tag attribute with its leading space, or nothing.
std::string tag_attribute(const Series& s) {
  return s.tag.empty() ? std::string() : " data-tag=\"" + escape(s.tag) + "\"";
}

// Dots are zero-length round-capped subpaths: one path element per series, and a dot that lands
// in the same half-pixel cell as an earlier one of its series is left out (it would be drawn
// over it).
void append_dots(std::string& o, const Frame& f, const Series& s, const Axis& ax, const Axis& ay) {
  const double W = f.W, H = f.H;
  const std::size_t n = std::min(s.x.size(), s.y.size());
  o += fmt::format(
      "<path fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" stroke-linecap=\"round\" "
      "stroke-opacity=\"{}\"{} d=\"",
      escape(s.color), px(s.dot_size), fmt::format("{:.2f}", s.opacity), tag_attribute(s));
  // One bit per half-pixel cell of the whole image.
  const auto cols = static_cast<std::size_t>(2 * W) + 1, rows = static_cast<std::size_t>(2 * H) + 1;
  std::vector<bool> taken(cols * rows, false);
  for (std::size_t i = 0; i < n; ++i) {
    if (!ax.inside(s.x[i]) || !ay.inside(s.y[i])) continue;
    const double x = ax.map(s.x[i]), y = ay.map(s.y[i]);
    if (!(x >= 0 && x < W && y >= 0 && y < H)) continue;  // e.g. a range that overflowed
    const std::size_t cell =
        static_cast<std::size_t>(2 * y) * cols + static_cast<std::size_t>(2 * x);
    if (taken[cell]) continue;
    taken[cell] = true;
    o += 'M';
    append_px(o, x);
    o += ' ';
    append_px(o, y);
    o += "h0";
  }
  o += "\"/>\n";
}

// A line through the points inside the axes, lifted where a point is outside.
void append_line(std::string& o, const Series& s, const Axis& ax, const Axis& ay) {
  const std::size_t n = std::min(s.x.size(), s.y.size());
  std::string d;
  bool pen_down = false;
  for (std::size_t i = 0; i < n; ++i) {
    if (!ax.inside(s.x[i]) || !ay.inside(s.y[i])) {
      pen_down = false;
      continue;
    }
    d += pen_down ? 'L' : 'M';
    append_px(d, ax.map(s.x[i]));
    d += ' ';
    append_px(d, ay.map(s.y[i]));
    pen_down = true;
  }
  if (s.outline)
    o += "<path fill=\"none\" stroke=\"#ffffff\" stroke-width=\"4.2\" stroke-linejoin=\"round\" "
         "stroke-opacity=\"0.9\" d=\"" +
         d + "\"/>\n";
  o += fmt::format(
      "<path fill=\"none\" stroke=\"{}\" stroke-width=\"1.8\" stroke-linejoin=\"round\"{}{} "
      "d=\"",
      escape(s.color),
      s.dash.empty() ? std::string() : " stroke-dasharray=\"" + escape(s.dash) + "\"",
      tag_attribute(s));
  o += d + "\"/>\n";
}

// The legend below the x label.
void append_legend(std::string& o, const Frame& f, const std::vector<LegendItem>& legend,
                   double legend_rows) {
  const double H = f.H;
  for (const auto& item : legend) {
    const double x = kLeft + item.x, y = H - kLegendRow * (legend_rows - item.y) + 2;
    if (item.series->mark == Mark::Dots)
      o += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"3.2\" fill=\"{}\"/>\n", px(x + 10),
                       px(y - 4), escape(item.series->color));
    else
      o += fmt::format(
          "<line x1=\"{0}\" y1=\"{2}\" x2=\"{1}\" y2=\"{2}\" stroke=\"{3}\" "
          "stroke-width=\"2\"{4}/>\n",
          px(x), px(x + 20), px(y - 4), escape(item.series->color),
          item.series->dash.empty() ? std::string()
                                    : " stroke-dasharray=\"" + escape(item.series->dash) + "\"");
    o += fmt::format("<text x=\"{}\" y=\"{}\">{}</text>\n", px(x + 26), px(y),
                     escape(item.series->label));
  }
}

}  // namespace

std::string escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  // A byte that XML 1.0 does not allow in a document, or that is not UTF-8, is shown as the
  // text \xNN, as in terminal messages: one such byte in a label would make a standalone .svg
  // ill-formed, and a browser then draws none of it.
  const auto show_byte = [&out](char c) {
    static constexpr char kHex[] = "0123456789abcdef";
    const auto u = static_cast<unsigned char>(c);
    out += {'\\', 'x', kHex[u >> 4], kHex[u & 15]};
  };
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    const auto u = static_cast<unsigned char>(c);
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        if (u >= 0x80) {
          const std::size_t n = text::utf8_sequence_length(s, i);
          // C1 controls (U+0080 to U+009F) and the non-characters U+FFFE and U+FFFF are
          // escaped too: XML forbids the latter, HTML counts both as errors.
          const bool c1 = n == 2 && u == 0xc2 && static_cast<unsigned char>(s[i + 1]) < 0xa0;
          const bool nonchar = n == 3 && s.compare(i, 2, "\xef\xbf") == 0 &&
                               static_cast<unsigned char>(s[i + 2]) >= 0xbe;
          if (n == 0 || c1 || nonchar) {
            for (std::size_t k = 0; k < std::max<std::size_t>(n, 1); ++k) show_byte(s[i + k]);
          } else {
            out.append(s, i, n);
          }
          i += std::max<std::size_t>(n, 1) - 1;
        } else if ((u < 0x20 && c != '\t' && c != '\n' && c != '\r') || u == 0x7f) {
          show_byte(c);
        } else {
          out += c;
        }
    }
  }
  return out;
}

std::string tick_label(double v) {
  if (v == 0) return "0";
  return fmt::format("{:.4g}", v);
}

std::vector<double> linear_ticks(double lo, double hi, int target) {
  std::vector<double> ticks;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return ticks;
  const double raw = (hi - lo) / std::max(target, 1);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10 * mag;
  for (double m : {1.0, 2.0, 5.0})
    if (m * mag >= raw) {
      step = m * mag;
      break;
    }
  const auto first = static_cast<long long>(std::ceil(lo / step - 1e-9));
  const auto last = static_cast<long long>(std::floor(hi / step + 1e-9));
  for (long long i = first; i <= last; ++i) ticks.push_back(static_cast<double>(i) * step);
  return ticks;
}

std::vector<double> log_ticks(double lo, double hi) {
  std::vector<double> ticks;
  if (!(lo > 0) || !(hi > lo) || !std::isfinite(hi)) return ticks;
  const int d0 = static_cast<int>(std::floor(std::log10(lo))) - 1;
  const int d1 = static_cast<int>(std::ceil(std::log10(hi))) + 1;
  const int stride = d1 - d0 > 16 ? 2 : 1;  // keep labels apart over very wide ranges
  for (int k = d0; k <= d1; ++k)
    if (k % stride == 0)
      if (const double t = std::pow(10.0, k); t >= lo && t <= hi) ticks.push_back(t);
  if (ticks.size() < 3) {
    ticks.clear();
    for (int k = d0; k <= d1; ++k)
      for (double m : {1.0, 2.0, 5.0})
        if (const double t = m * std::pow(10.0, k); t >= lo && t <= hi) ticks.push_back(t);
  }
  return ticks;
}

std::string standalone_file(const std::string& svg_element) {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  if (svg_element.compare(0, 4, "<svg") == 0)
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\"" + svg_element.substr(4);
  else
    out += svg_element;
  return out + "\n";
}

std::string render(const Plot& p) {
  // Legend layout first: its rows take space below the axes; the title and notes above them.
  const std::vector<LegendItem> legend = legend_layout(p);
  const double legend_rows = legend.empty() ? 0 : legend.back().y + 1;
  Frame f;
  f.W = p.width;
  f.title = wrap(p.title, f.W - 8, kTitleCharWidth);
  for (const auto& note : p.notes)
    for (auto& l : wrap(note, f.W - 8, kCharWidth)) f.notes.push_back(std::move(l));
  f.top = kTitleLine + kTitleRow * static_cast<double>(f.title.size() - 1) +
          kNoteLine * static_cast<double>(f.notes.size()) + 14;
  f.bottom = kBelowAxis + kLegendRow * legend_rows + 4;
  f.H = std::max(static_cast<double>(p.height), f.top + kMinAxesHeight + f.bottom);

  Axis ax, ay;
  ax.log = p.log_x, ay.log = p.log_y;
  ax.from = kLeft, ax.to = f.W - kRight;
  ay.from = f.H - f.bottom, ay.to = f.top;
  set_ranges(p, ax, ay);

  std::string o;
  o.reserve(4096);
  append_header(o, p, f);
  append_axes(o, p, ax, ay);
  append_markers(o, p, ax, ay);
  for (const auto& s : p.series) {
    if (s.mark == Mark::Dots)
      append_dots(o, f, s, ax, ay);
    else
      append_line(o, s, ax, ay);
  }
  append_legend(o, f, legend, legend_rows);
  o += "</svg>";
  return o;
}

}  // namespace frictionid::svg
