// Sum of ln x over many x with one std::log per block of values instead of one per value: the
// noise model's likelihoods and ln det Sigma (noise_model.cpp, noise_reweighting.cpp) sum a log
// for every row of every channel on every reweighting pass, and the logs were their largest cost.
//
// x = m 2^e with m in [1, 2) exactly (the bits of x), so ln x = ln m + e ln 2: the exponents sum
// exactly as integers, and the mantissas of a block of 32 multiply below 2^32, where one log of
// their product costs what one row's did. Its rounding (about 32 ulp of the block's product) is
// below that of summing 32 rounded logs. Values that are not positive normal doubles (0,
// subnormal, negative, inf, nan) take std::log one by one, so the sum is -inf, nan or inf exactly
// when summing std::log would give it.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

namespace frictionid {

class LogSum {
 public:
  void add(double x) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const auto biased = static_cast<int>(bits >> 52);  // sign bit included: negative is >= 2048
    if (biased == 0 || biased >= 0x7ff) {
      special_ += std::log(x);
      return;
    }
    exponent_ += biased - 1023;
    bits = (bits & kMantissa) | kOne;
    double m;
    std::memcpy(&m, &bits, sizeof m);
    product_ *= m;
    if (++count_ == kBlock) {
      logs_ += std::log(product_);
      product_ = 1.0;
      count_ = 0;
    }
  }

  double sum() const { return sum_of(exponent_, logs_, product_, special_); }

  // For code that keeps a LogSum's state in its own form (variance_profile.cpp: one per vector
  // lane): values go a block of kBlock at a time, the exponents summed, the mantissas (bits
  // kMantissa with those of kOne) multiplied into the block's product, ln of a full block's
  // product added to logs. The sum of that state, as sum() forms it.
  static constexpr int kBlock = 32;
  static constexpr std::uint64_t kMantissa = 0x000fffffffffffffULL, kOne = 0x3ff0000000000000ULL;
  static double sum_of(long long exponent, double logs, double product, double special) {
    // ln 2 in two parts (fdlibm's): e ln2_hi is exact for |e| < 2^21, the rest is rounding.
    constexpr double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10;
    const auto e = static_cast<double>(exponent);
    return (e * ln2_hi + (logs + std::log(product))) + e * ln2_lo + special;
  }

 private:
  double product_ = 1.0;  // mantissas of the open block
  int count_ = 0;         // values in the open block
  double logs_ = 0.0;     // ln of the closed blocks' products
  long long exponent_ = 0;
  double special_ = 0.0;  // std::log of the values outside the normal range
};

}  // namespace frictionid
