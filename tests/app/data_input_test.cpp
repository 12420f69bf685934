// A request's data options and the checks on wheel-form data (app/data_input.hpp): the option
// values, the rolling direction a standing wheel lacks, the columns a batch keeps, and the
// options' round trip through the request's JSON (the batch journal, the Dask workers).
#include "app/data_input.hpp"

#include <gtest/gtest.h>

#include <string>

#include <frictionid/io/input_error.hpp>
#include "app/fit_request.hpp"
#include "app/option_parsers.hpp"
#include "app/request_json.hpp"

namespace frictionid::app::data_input_test {
namespace {

// Two rows of a wheel-form dataset; the second wheel stands still when `standing`.
Dataset wheel_rows(bool standing) {
  Dataset d;
  d.source = "w.csv";
  d.line = {2, 3};
  d.v_x = {0.1, 0.2};
  d.v_y = {0.0, 0.0};
  d.omega = {1.0, 1.0};
  d.N = {1000.0, 1000.0};
  d.R = {0.05, 0.05};
  d.tilt_sign = {1.0, standing ? 0.0 : -1.0};
  for (int c = 0; c < kChannelCount; ++c) {
    d.value[c] = {1.0, 1.0};
    d.present[c] = {c == 0, c == 0};
  }
  d.extra_names = {"tire", "pressure"};
  d.extra_values = {{"A", "A"}, {"240", "250"}};
  return d;
}

TEST(DataInput, AStandingWheelNeedsHFixedAtZero) {
  FitRequest r;
  const FitSettings free_h = fit_settings(r, "seed");
  try {
    check_rolling_direction(free_h, wheel_rows(true));
    FAIL() << "a free h was accepted with a standing wheel";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "w.csv");
    EXPECT_EQ(e.line(), 3u);
    EXPECT_NE(e.message().find("--fix h=0"), std::string::npos) << e.what();
  }
  r.fix = {{"h", 0.0}};
  EXPECT_NO_THROW(check_rolling_direction(fit_settings(r, "seed"), wheel_rows(true)));
  r.fix = {{"h", 0.05}};  // a tilt fixed away from 0 still needs a direction
  EXPECT_THROW(check_rolling_direction(fit_settings(r, "seed"), wheel_rows(true)), InputError);
}

TEST(DataInput, RollingWheelsNeedNothing) {
  EXPECT_NO_THROW(check_rolling_direction(fit_settings(FitRequest{}, "seed"), wheel_rows(false)));
  Dataset native = wheel_rows(true);
  native.tilt_sign.clear();  // the native form: the tilt along +x, no rolling direction asked
  EXPECT_NO_THROW(check_rolling_direction(fit_settings(FitRequest{}, "seed"), native));
}

TEST(DataInput, KeptColumnsTakeTheRunsValue) {
  const auto kept = kept_columns(wheel_rows(false), {"tire", "pressure"});
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0].name, "tire");
  EXPECT_EQ(std::get<std::string>(kept[0].value), "A");
  EXPECT_EQ(std::get<std::string>(kept[1].value), "240|250");  // the rows differ: both, in order
}

TEST(DataInput, KeepingAColumnTheDataLacksNamesTheColumnsItHas) {
  try {
    kept_columns(wheel_rows(false), {"run"});
    FAIL() << "--keep run accepted";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("tire, pressure"), std::string::npos) << e.what();
  }
}

TEST(DataInput, UnknownFormOrAxesOrABadRadiusNameTheOption) {
  FitRequest r;
  r.input_form = "rig";
  EXPECT_THROW(dataset_read_options(r), InputError);
  r.input_form = "wheel";
  r.axes = "nasa";
  EXPECT_THROW(dataset_read_options(r), InputError);
  r.axes = "sae";
  r.contact_radius = -0.05;
  EXPECT_THROW(dataset_read_options(r), InputError);
  r.contact_radius = 0.05;
  const DatasetReadOptions o = dataset_read_options(r);
  EXPECT_EQ(o.form, InputForm::Wheel);
  EXPECT_EQ(o.axes, Axes::Sae);
  EXPECT_EQ(o.contact_radius, 0.05);
}

TEST(DataInput, DataOptionsSurviveTheRequestJsonAndLeaveDefaultsOut) {
  FitRequest r;
  EXPECT_FALSE(fit_request_json(r).contains("input_form"));  // a native fit's options unchanged
  EXPECT_FALSE(fit_request_json(r).contains("keep"));
  r.input_form = "wheel";
  r.axes = "sae";
  r.contact_radius = 0.0375;
  r.keep = {"tire", "pressure"};
  const FitRequest back = fit_request_from_json(fit_request_json(r));
  EXPECT_EQ(back.input_form, "wheel");
  EXPECT_EQ(back.axes, "sae");
  EXPECT_EQ(back.contact_radius, 0.0375);
  EXPECT_EQ(back.keep, r.keep);
}

TEST(DataInput, ColumnMapsTakeWheelFormNames) {
  const ColumnMap m = parse_column_map("r_e=RLOADED,Fz=load");
  EXPECT_EQ(m.canonical_to_header.at("r_e"), "RLOADED");
  EXPECT_THROW(parse_column_map("alfa=SA"), InputError);
}

}  // namespace
}  // namespace frictionid::app::data_input_test
