// Requests on a contact spot (--contact, --free): which parameters are fitted and held on each
// spot, what the data's M_tilt column changes, the checks every front end gets (a map with
// --pressure, a non-circular spot on an approximant, a tilt that makes the pressure negative), and
// a circle's request text that stays what it was.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <string>

#include <frictionid/io/input_error.hpp>
#include "app/fit_request.hpp"
#include "app/law_coefficients.hpp"
#include "app/model_setup.hpp"
#include "app/request_json.hpp"
#include "app/request_text.hpp"
#include "app/requests.hpp"

namespace frictionid::app::contact_requests_test {
namespace {

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return "";
}

::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

FitRequest exact_on(const std::string& contact) {
  FitRequest r;
  r.model = "exact";
  r.contact = contact;
  return r;
}

// A file for the test, removed at its end, named for the test: ctest runs the tests of this
// file in parallel processes, and one test's file removed under another failed it.
struct TempFile {
  std::string path;
  TempFile(const std::string& name, const std::string& text)
      : path(::testing::TempDir() + "contact_requests_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" + name) {
    std::FILE* f = std::fopen(path.c_str(), "w");
    std::fputs(text.c_str(), f);
    std::fclose(f);
  }
  ~TempFile() { std::remove(path.c_str()); }
};

const char* const kMap = "x,y,sigma0\n-1,-1,0\n0,-1,1\n1,-1,0\n-1,1,0\n0,1,1\n1,1,0\n";

// A dataset of two rows that measures `channels`.
Dataset rows_measuring(std::initializer_list<Channel> channels) {
  Dataset d;
  d.source = "rows.csv";
  for (int i = 0; i < 2; ++i) {
    d.v_x.push_back(0.1 * (i + 1));
    d.v_y.push_back(0.0);
    d.omega.push_back(2.0);
    d.N.push_back(1000.0);
    d.R.push_back(0.05);
  }
  for (Channel c : kAllChannels) {
    const int k = static_cast<int>(c);
    d.value[k].assign(2, 0.0);
    d.present[k].assign(2, 0);
  }
  for (Channel c : channels) {
    d.value[static_cast<int>(c)].assign(2, 1.0);
    d.present[static_cast<int>(c)].assign(2, 1);
  }
  return d;
}

TEST(ContactRequest, OnTheCircleHyAndQAreHeldAsBefore) {
  const FitSettings s = fit_settings(exact_on("circle"), "exact");
  EXPECT_EQ(s.contact.kind, model::SpotKind::Circle);
  EXPECT_TRUE(s.params[kHy].fixed);
  EXPECT_EQ(s.params[kHy].initial, 0.0);
  EXPECT_TRUE(s.params[kQ].fixed);
  EXPECT_EQ(s.used_parameters(), (std::vector<int>{kF, kKappa, kH}));
}

TEST(ContactRequest, OnAnEllipseHyIsFittedAndQHeldAtTheSpotsAspect) {
  const FitSettings s = fit_settings(exact_on("ellipse:0.7"), "exact");
  EXPECT_EQ(s.contact.kind, model::SpotKind::Ellipse);
  EXPECT_EQ(s.contact.q, 0.7);
  EXPECT_FALSE(s.params[kHy].fixed);
  EXPECT_TRUE(s.params[kQ].fixed);
  EXPECT_EQ(s.params[kQ].initial, 0.7);
}

TEST(ContactRequest, FreeQFitsTheAspectFromTheSpotsValue) {
  FitRequest r = exact_on("rect:0.5");
  r.free = {"q"};
  const FitSettings s = fit_settings(r, "exact");
  EXPECT_FALSE(s.params[kQ].fixed);
  EXPECT_EQ(s.params[kQ].initial, 0.5);
}

TEST(ContactRequest, AFittedMTiltColumnFreesHyOnTheCircleUnlessFixed) {
  const Dataset with_tilt = rows_measuring({Channel::T_x, Channel::M_tilt});
  const Dataset without = rows_measuring({Channel::T_x});
  EXPECT_FALSE(fit_settings(exact_on("circle"), "exact", with_tilt).params[kHy].fixed);
  EXPECT_TRUE(fit_settings(exact_on("circle"), "exact", without).params[kHy].fixed);
  FitRequest other_channels = exact_on("circle");
  other_channels.channels = {"T_x"};
  EXPECT_TRUE(fit_settings(other_channels, "exact", with_tilt).params[kHy].fixed);
  FitRequest fixed = exact_on("circle");
  fixed.fix = {{"h_y", 0.02}};
  const FitSettings s = fit_settings(fixed, "exact", with_tilt);
  EXPECT_TRUE(s.params[kHy].fixed);
  EXPECT_EQ(s.params[kHy].initial, 0.02);
}

TEST(ContactRequest, FreeQOnTheCircleOrAMapIsRejected) {
  FitRequest circle = exact_on("circle");
  circle.free = {"q"};
  EXPECT_TRUE(Contains(message_of([&] { fit_settings(circle, "exact"); }),
                       "--free q: q is the aspect of --contact ellipse:Q or rect:Q; the circle "
                       "has none to fit"));
  const TempFile map("map.csv", kMap);
  FitRequest on_map = exact_on("map:" + map.path);
  on_map.free = {"q"};
  EXPECT_TRUE(
      Contains(message_of([&] { fit_settings(on_map, "exact"); }), "a pressure map has none"));
}

TEST(ContactRequest, FreeAndFixOfOneParameterIsRejected) {
  FitRequest r = exact_on("ellipse:0.7");
  r.free = {"h_y"};
  r.fix = {{"h_y", 0.0}};
  EXPECT_TRUE(Contains(message_of([&] { fit_settings(r, "exact"); }),
                       "--free h_y and --fix h_y=...: a parameter is either fitted or held"));
}

TEST(ContactRequest, TheAspectIsGivenWithTheSpotNotAsAParameter) {
  FitRequest fix = exact_on("ellipse:0.7");
  fix.fix = {{"q", 0.8}};
  EXPECT_TRUE(Contains(message_of([&] { fit_settings(fix, "exact"); }), "--fix q=..."));
  FitRequest start = exact_on("ellipse:0.7");
  start.start = {{"q", 0.8}};
  start.no_global = true;
  EXPECT_TRUE(Contains(message_of([&] { fit_settings(start, "exact"); }), "add --free q"));
  EXPECT_TRUE(Contains(message_of([] {
                         make_model_setup({"exact", "hertz", {{"q", 0.8}}, "ellipse:0.7", false});
                       }),
                       "--param q=...: q is the aspect of the contact spot"));
}

TEST(ContactRequest, ANonCircularSpotOnAnApproximantNeedsTheExactModel) {
  for (const char* model : {"seed", "corrected"}) {
    FitRequest r = exact_on("ellipse:0.7");
    r.model = model;
    const std::string m = message_of([&] { fit_settings(r, model); });
    EXPECT_TRUE(Contains(m, "--contact: 'ellipse:0.7'")) << m;
    EXPECT_TRUE(Contains(m, "needs --model exact")) << m;
    EXPECT_TRUE(Contains(message_of([&] {
                           make_model_setup({model, "hertz", {}, "rect:1"});
                         }),
                         "needs --model exact"));
  }
}

TEST(ContactRequest, PressureGivenWithAMapIsRejected) {
  const TempFile map("map.csv", kMap);
  FitRequest r = exact_on("map:" + map.path);
  r.pressure = "hertz";
  r.pressure_given = true;
  EXPECT_TRUE(Contains(message_of([&] { fit_settings(r, "exact"); }),
                       "--pressure: a pressure map (--contact map:"));
  EXPECT_TRUE(Contains(message_of([&] {
                         make_model_setup({"exact", "parabolic", {}, "map:" + map.path, true});
                       }),
                       "leave --pressure out with map:FILE"));
  EXPECT_TRUE(Contains(message_of([&] {
                         law_coefficients({"hertz", 1.0, 0.0, "map:" + map.path, true});
                       }),
                       "--pressure: a pressure map"));
  // Not given: the map is the pressure, and reports call the law "map".
  r.pressure_given = false;
  EXPECT_EQ(fit_settings(r, "exact").law_label, "map");
}

TEST(ContactRequest, ATiltThatMakesThePressureNegativeNamesHHyAndThePoint) {
  const std::string m = message_of([] {
    make_model_setup({"exact", "hertz", {{"h", 0.0}, {"h_y", 2.0}}, "rect:0.7"});
  });
  EXPECT_TRUE(Contains(m,
                       "--param: h = 0, h_y = 2 make the pressure 1 + h x + h_y y negative at "
                       "(x, y) = (-1, -0.7) of the contact spot rect:0.7"))
      << m;
  FitRequest fixed = exact_on("ellipse:0.5");
  fixed.fix = {{"h", 0.9}, {"h_y", 0.9}};
  EXPECT_TRUE(Contains(message_of([&] { fit_settings(fixed, "exact"); }), "--fix: h = 0.9"));
  // Inside the bounds and within the spot, a tilt is fine.
  fixed.fix = {{"h", 0.5}, {"h_y", 0.5}};
  EXPECT_NO_THROW(fit_settings(fixed, "exact"));
}

TEST(ContactRequest, ModelsOnASpotShowTheirMTilt) {
  EXPECT_FALSE(shows_tilt(make_model_setup({"exact", "hertz", {}})));
  EXPECT_TRUE(shows_tilt(make_model_setup({"exact", "hertz", {{"h_y", 0.1}}})));
  const ModelSetup s = make_model_setup({"exact", "hertz", {}, "ellipse:0.6"});
  EXPECT_TRUE(shows_tilt(s));
  const auto j = model_json(s);
  EXPECT_EQ(j["contact"], "ellipse:0.6");
  EXPECT_EQ(j["parameters"]["q"], 0.6);
  EXPECT_FALSE(model_json(make_model_setup({"exact", "hertz", {}})).contains("contact"));
}

TEST(ContactRequestJson, ARoundTripKeepsTheSpotAndTheFreedParameters) {
  FitRequest r = exact_on("ellipse:0.7");
  r.free = {"q"};
  const FitRequest back = fit_request_from_json(fit_request_json(r));
  EXPECT_EQ(back.contact, "ellipse:0.7");
  EXPECT_EQ(back.free, std::vector<std::string>{"q"});
  EXPECT_EQ(fit_request_json(back), fit_request_json(r));
}

TEST(ContactRequestJson, ACirclesRequestTextHasNoSpotAndNoFreedParameters) {
  // The provenance of every report and every batch journal key: unchanged for the circle.
  const auto j = fit_request_json(FitRequest{});
  EXPECT_FALSE(j.contains("contact"));
  EXPECT_FALSE(j.contains("free"));
  std::vector<std::string> keys;
  for (auto it = j.begin(); it != j.end(); ++it) keys.push_back(it.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"model", "pressure", "fix", "bounds", "start", "loss",
                                            "channels", "columns", "noise_model", "intervals",
                                            "bootstrap", "starts", "seed", "global_evaluations",
                                            "global_subsample", "no_global", "global_algorithm"}));
}

TEST(ContactRequestText, FreeIsReadAsANameList) {
  FitRequest r;
  FitText text;
  text.free = "h_y, q";
  apply(text, r);
  EXPECT_EQ(r.free, (std::vector<std::string>{"h_y", "q"}));
}

TEST(ContactCoefficients, AnEllipseOfAspectOneHasTheCirclesCoefficients) {
  const auto circle = law_coefficients({"hertz", 1.3, 0.0});
  const auto ellipse = law_coefficients({"hertz", 1.3, 0.0, "ellipse:1"});
  EXPECT_EQ(ellipse["contact"], "ellipse:1");
  for (const char* name : {"a", "b", "m", "b_tilde", "p0", "mu_M", "M_roll_per_hNR"}) {
    const double want = circle[name].get<double>(), got = ellipse[name].get<double>();
    EXPECT_NEAR(got, want, 1e-6 * want) << name;
  }
  EXPECT_TRUE(Contains(message_of([] {
                         law_coefficients({"hertz", 1.0, 0.3, "rect:0.5"});
                       }),
                       "--alpha"));
}

}  // namespace
}  // namespace frictionid::app::contact_requests_test
