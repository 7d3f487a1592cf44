// The one Monte Carlo estimator of luxplan: a running mean and standard error of the mean
// over the samples of one point (sampler item, work-plane cell, pixel).
//
// NaN/inf policy, the same everywhere: a non-finite sample is dropped and counted, never
// added. Mean, variance and error are over the finite samples alone (n = count()), and
// dropped() tells callers how many were left out. With no finite sample they are all 0.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace luxplan {

class MeanEstimator {
public:
    void add(double x) {
        if (!std::isfinite(x)) {
            ++dropped_;
            return;
        }
        sum_ += x;
        sumSquares_ += x * x;
        ++count_;
    }

    // n samples that are exactly 0 (a path that added nothing to this estimate).
    void addZeros(uint64_t n) { count_ += n; }
    // The estimator of both sample sets together.
    void merge(const MeanEstimator& o) {
        sum_ += o.sum_, sumSquares_ += o.sumSquares_, count_ += o.count_, dropped_ += o.dropped_;
    }

    // The estimator of this one's samples less `part`'s, which must be a subset of them
    // (merged in earlier): a fold held out of a total.
    MeanEstimator without(const MeanEstimator& part) const {
        MeanEstimator r = *this;
        r.sum_ -= part.sum_, r.sumSquares_ -= part.sumSquares_, r.count_ -= part.count_, r.dropped_ -= part.dropped_;
        return r;
    }

    uint64_t count() const { return count_; }
    // Every sample kept was zero (or none was): mean and variance are exactly 0.
    bool allZero() const { return sum_ == 0 && sumSquares_ == 0; }
    uint64_t dropped() const { return dropped_; }

    double mean() const { return count_ > 0 ? sum_ / double(count_) : 0.0; }
    // Unbiased sample variance, max(0, E[x^2] - mean^2) n / (n - 1); 0 for n < 2.
    double variance() const {
        if (count_ == 0) return 0;
        const double n = double(count_), m = sum_ / n;
        return std::max(0.0, sumSquares_ / n - m * m) * n / std::max(1.0, n - 1);
    }
    double standardError() const { return count_ > 0 ? std::sqrt(variance() / double(count_)) : 0.0; }
    // standardError()^2 up to rounding, evaluated as max(0, E[x^2] - mean^2) / (n - 1): the
    // renderer's per-pixel variance has always been this form, and keeping it keeps images
    // bit-identical. 0 for n < 2.
    double varianceOfMean() const {
        if (count_ < 2) return 0;
        const double n = double(count_), m = sum_ / n;
        return std::max(0.0, sumSquares_ / n - m * m) / (n - 1);
    }

private:
    double sum_ = 0, sumSquares_ = 0;
    uint64_t count_ = 0, dropped_ = 0;
};

}  // namespace luxplan
