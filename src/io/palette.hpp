// The colours of every plot frictionid draws (docs/design.md §4.3, "Colours"): one categorical
// palette for series told apart by colour (groups of rows, models, runs, parameter values), and
// two neutral colours for what is not a category.
#pragma once

#include <array>
#include <cstddef>

namespace frictionid::palette {

// Okabe and Ito's colour-blind-safe set ("Color Universal Design", 2008) without its black, in
// this order: blue, vermillion, bluish green, reddish purple, orange, sky blue, yellow. Under a
// simulated deuteranopia, protanopia or tritanopia every two of them stay apart (CIELAB ΔE
// above 15; tests/io/palette_test.cpp).
inline constexpr std::array<const char*, 7> kSeries = {"#0072b2", "#d55e00", "#009e73", "#cc79a7",
                                                       "#e69f00", "#56b4e9", "#f0e442"};

// Okabe and Ito's black: the fitted model where it is drawn as dots, reference lines (y = x).
// No category has it, so it never reads as one.
inline constexpr const char* kReference = "#000000";

// Grey: data drawn behind the series (the measured values under every model of a comparison,
// stable points of a shimmy sweep).
inline constexpr const char* kBackdrop = "#999999";

// The k-th series colour; they repeat after kSeries.size().
inline const char* series(std::size_t k) {
  return kSeries[k % kSeries.size()];
}

}  // namespace frictionid::palette
