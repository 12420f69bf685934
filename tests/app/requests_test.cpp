// The app layer's requests: a request built from typed values (as Python builds it) and one
// parsed from the command line's text give the same settings; the checks hold whichever front end
// built the request.
#include "app/requests.hpp"

#include <gtest/gtest.h>

#include <string>

#include <frictionid/io/input_error.hpp>
#include "app/fit_request.hpp"
#include "app/generation.hpp"
#include "app/option_parsers.hpp"
#include "app/request_json.hpp"
#include "app/request_text.hpp"

namespace frictionid::app::requests_test {
namespace {

// Every field of the settings that a request can change.
void expect_same_settings(const FitSettings& a, const FitSettings& b) {
  ASSERT_EQ(a.params.size(), b.params.size());
  for (std::size_t i = 0; i < a.params.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(a.params[i].initial, b.params[i].initial);
    EXPECT_EQ(a.params[i].lower, b.params[i].lower);
    EXPECT_EQ(a.params[i].upper, b.params[i].upper);
    EXPECT_EQ(a.params[i].fixed, b.params[i].fixed);
  }
  EXPECT_EQ(a.channels, b.channels);
  EXPECT_EQ(a.loss, b.loss);
  EXPECT_EQ(a.loss_scale, b.loss_scale);
  EXPECT_EQ(a.noise_model, b.noise_model);
  EXPECT_EQ(a.seed, b.seed);
  EXPECT_EQ(a.global, b.global);
  EXPECT_EQ(a.law_label, b.law_label);
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return "";
}

TEST(FitRequest, TypedValuesGiveTheSettingsOfTheCommandLinesText) {
  FitRequest typed;
  typed.model = "exact";
  typed.fix = {{"kappa", 1.25}};
  typed.bounds = {{"f", {0.2, 1.7}}, {"h", {-0.3, 0.4}}};
  typed.start = {{"f", 0.9}, {"h", 0.05}};
  typed.no_global = true;
  typed.channels = {"M_z", "T_x"};
  typed.loss = "huber:2.5";
  typed.seed = 77;

  FitRequest parsed = typed;
  parsed.fix.clear();
  parsed.bounds.clear();
  parsed.start.clear();
  parsed.channels.clear();
  apply(FitText{"kappa=1.25", "f=0.2:1.7,h=-0.3:0.4", "f=0.9,h=0.05", "M_z,T_x", "", ""}, parsed);

  expect_same_settings(fit_settings(typed, typed.model), fit_settings(parsed, parsed.model));
}

TEST(FitRequest, ASeedPastThirtyTwoBitsIsRejectedWithTheCommandLinesRange) {
  FitRequest r;
  r.seed = 4294967296ULL;
  const std::string m = message_of([&] { (void)fit_settings(r, r.model); });
  EXPECT_NE(m.find("--seed"), std::string::npos) << m;
  EXPECT_NE(m.find("from 0 to 4294967295"), std::string::npos) << m;
  r.seed = 4294967295ULL;
  EXPECT_EQ(fit_settings(r, r.model).seed, 4294967295ULL);
}

TEST(FitRequest, NonFiniteValuesAndEmptyRangesAreRejectedNamingTheOption) {
  FitRequest r;
  r.fix = {{"kappa", std::nan("")}};
  EXPECT_NE(message_of([&] { (void)fit_settings(r, r.model); }).find("--fix"), std::string::npos);
  r.fix.clear();
  r.bounds = {{"f", {1.0, 1.0}}};
  EXPECT_NE(message_of([&] { (void)fit_settings(r, r.model); }).find("--bounds"),
            std::string::npos);
  r.bounds.clear();
  r.channels = {"T_x", "T_x"};
  EXPECT_NE(message_of([&] { (void)fit_settings(r, r.model); }).find("more than once"),
            std::string::npos);
}

TEST(FitRequest, AnUnknownGlobalAlgorithmIsRejectedWhicheverFrontEndBuiltIt) {
  FitRequest r;
  r.global_algorithm = "crs3";
  EXPECT_NE(message_of([&] { (void)fit_settings(r, r.model); }).find("--global-algorithm"),
            std::string::npos);
}

TEST(FitRequestJson, ARoundTripKeepsEveryFieldTheFitReads) {
  FitRequest r;
  r.model = "corrected";
  r.pressure = "power:1.5";
  r.fix = {{"h", 0.1}};
  r.bounds = {{"f", {0.1, 3.0}}};
  r.start = {{"f", 0.7}};
  r.no_global = true;
  r.loss = "cauchy:1.5";
  r.channels = {"T_y"};
  r.columns = parse_column_map("v_x=speed");
  r.noise_model = "relative";
  r.intervals = "profile";
  r.bootstrap = 12;
  r.starts = 3;
  r.seed = 9;
  r.global_evaluations = 500;
  r.global_subsample = 123;
  r.global_algorithm = "direct";
  const FitRequest back = fit_request_from_json(fit_request_json(r));
  EXPECT_EQ(fit_request_json(back), fit_request_json(r));
  EXPECT_EQ(back.columns.canonical_to_header, r.columns.canonical_to_header);
  expect_same_settings(fit_settings(back, back.model), fit_settings(r, r.model));
}

TEST(ColumnMap, AMapGivenAsPairsGetsTheMessagesOfTheText) {
  const std::string from_text = message_of([] { (void)parse_column_map("omgea=spin"); });
  const std::string from_map = message_of([] { (void)column_map({{"omgea", "spin"}}); });
  EXPECT_EQ(from_map, from_text);
  EXPECT_NE(from_map.find("did you mean 'omega'"), std::string::npos) << from_map;
  EXPECT_EQ(column_map({{"v_x", "speed"}}).canonical_to_header.at("v_x"), "speed");
}

TEST(GenerateRequest, RowsOutsideTheCommandLinesRangeAreRefusedBeforeAnyWork) {
  GenerateRequest r;
  r.rows = 1'000'000'000'000ULL;
  EXPECT_NE(message_of([&] { (void)generate(r); }).find("from 1 to 10000000"), std::string::npos);
  r.rows = 0;
  EXPECT_NE(message_of([&] { (void)generate(r); }).find("--rows"), std::string::npos);
}

TEST(RequestText, SharedNamesRejectAnEmptyName) {
  EXPECT_EQ(shared_names("kappa,h"), (std::vector<std::string>{"kappa", "h"}));
  EXPECT_NE(message_of([] { (void)shared_names("kappa,"); }).find("expected P[,P]"),
            std::string::npos);
}

}  // namespace
}  // namespace frictionid::app::requests_test
