// The whole user path through the public API: read a dataset, choose a model and a pressure
// law, fit, print the parameters with their standard errors, and write a report.
//
//   fit_from_csv DATA.csv [LAW] [REPORT_DIR]     (LAW defaults to hertz)
#include <cstdio>
#include <exception>
#include <string>

#include <frictionid/frictionid.hpp>

namespace {

// Prints the global and local progress on one line; a GUI would update a progress bar instead.
class ProgressLine : public frictionid::FitObserver {
 public:
  void on_progress(const frictionid::FitProgress& p) override {
    if (p.stage == frictionid::FitStage::LocalFit)
      std::fprintf(stderr, "\rlocal fit %d/%d, iteration %ld   ", p.start, p.starts, p.done);
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s DATA.csv [LAW] [REPORT_DIR]\n", argv[0]);
    return 2;
  }
  const std::string law_text = argc > 2 ? argv[2] : "hertz";
  try {
    const frictionid::Dataset data = frictionid::load_dataset_csv(argv[1]);
    const auto law = frictionid::parse_pressure_law(law_text);

    auto settings = frictionid::FitSettings::defaults(
        frictionid::ModelKind::Exact, law, frictionid::pressure_law_label(law, law_text));
    settings.bound("kappa", 0.5, 3.0);  // what we know of this tire
    std::string why;
    if (!settings.validate(&why)) {
      std::fprintf(stderr, "settings: %s\n", why.c_str());
      return 2;
    }

    ProgressLine progress;
    const frictionid::FitResult result = frictionid::Fitter(settings).fit(data, &progress);
    std::fprintf(stderr, "\n");

    std::printf("%s model, %s pressure, %zu rows\n", result.model.c_str(), result.pressure.c_str(),
                result.rows);
    for (const auto& p : result.parameters)
      std::printf("%-6s %.8g +- %.2g\n", p.name.c_str(), p.value, p.std_error.value_or(0.0));
    std::printf("reduced chi2 %.4g\n", result.reduced_chi2);
    for (const auto& w : result.warnings) std::printf("warning: %s\n", w.c_str());

    if (argc > 3) frictionid::write_report(argv[3], result, data);
    return 0;
  } catch (const frictionid::InputError& e) {  // bad file or law, with file:line:column
    std::fprintf(stderr, "input: %s\n", e.what());
    return 2;
  } catch (const frictionid::FitError& e) {  // the fit failed or was cancelled
    std::fprintf(stderr, "fit failed: %s\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
