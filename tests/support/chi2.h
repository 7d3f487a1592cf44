// Pearson chi-square goodness-of-fit for sampling tests (pbrt / Mitsuba style):
// pool cells with small expected counts, then compare to the chi-square law.
#pragma once

#include <string>
#include <vector>

namespace luxplan::test {

struct Chi2Result {
    double statistic = 0;
    int dof = 0;
    double pValue = 1;
    std::string table;  // observed vs expected per (pooled) cell, for failure messages
};

// Regularized upper incomplete gamma Q(a, x).
double incompleteGammaQ(double a, double x);

// Survival function of the chi-square distribution with `dof` degrees of freedom.
double chi2Survival(double statistic, int dof);

// observed and expected counts per cell (same length, expected summing to the
// sample count). Cells with expected < minExpected are pooled together.
Chi2Result chi2Test(const std::vector<double>& observed, const std::vector<double>& expected,
                    double minExpected = 5.0);

// Significance level for one of `numTests` tests at family level alpha (Sidak).
double sidakAlpha(double alpha, int numTests);

}  // namespace luxplan::test
