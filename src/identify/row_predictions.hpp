// A model's resultants at many rows on several threads (eval, generate): each row is computed by
// itself, from the same evaluator, so the values are the same bits on any number of threads.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include <frictionid/model/kinematics.hpp>
#include <frictionid/model_variant.hpp>

namespace frictionid {

// model(kinematics(i)) for every i in [0, rows), on up to `threads` threads (0: every hardware
// thread; fewer when the calling thread's budget has fewer, thread_budget.hpp). A row of a
// non-circular spot integrated by itself costs 6-400 us, so the rows go out a few at a time.
std::vector<model::Resultants<double>> predict_rows(
    const ModelEvaluator<double>& model, std::size_t rows,
    const std::function<model::Kinematics(std::size_t)>& kinematics, int threads);

}  // namespace frictionid
