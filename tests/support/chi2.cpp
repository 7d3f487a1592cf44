#include "support/chi2.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace luxplan::test {

// Numerical Recipes style: series for x < a+1, Lentz continued fraction otherwise.
double incompleteGammaQ(double a, double x) {
    if (x <= 0) return 1.0;
    double gln = std::lgamma(a);
    if (x < a + 1) {
        double ap = a, sum = 1.0 / a, del = sum;
        for (int n = 0; n < 10000; ++n) {
            ap += 1;
            del *= x / ap;
            sum += del;
            if (std::abs(del) < std::abs(sum) * 1e-15) break;
        }
        return 1.0 - sum * std::exp(-x + a * std::log(x) - gln);
    }
    double b = x + 1 - a, c = 1.0 / 1e-300, d = 1.0 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        if (std::abs(d) < 1e-300) d = 1e-300;
        c = b + an / c;
        if (std::abs(c) < 1e-300) c = 1e-300;
        d = 1 / d;
        double del = d * c;
        h *= del;
        if (std::abs(del - 1) < 1e-15) break;
    }
    return std::exp(-x + a * std::log(x) - gln) * h;
}

double chi2Survival(double statistic, int dof) { return incompleteGammaQ(0.5 * dof, 0.5 * statistic); }

Chi2Result chi2Test(const std::vector<double>& observed, const std::vector<double>& expected, double minExpected) {
    if (observed.size() != expected.size()) throw std::invalid_argument("chi2Test: size mismatch");
    std::vector<size_t> order(observed.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });

    Chi2Result r;
    std::ostringstream table;
    double pooledObs = 0, pooledExp = 0;
    int cells = 0;
    auto addCell = [&](double o, double e, const std::string& label) {
        r.statistic += (o - e) * (o - e) / e;
        ++cells;
        table << label << ": observed " << o << " expected " << e << "\n";
    };
    for (size_t idx : order) {
        double e = expected[idx], o = observed[idx];
        if (e <= 0) {
            if (o > 0) {
                r.pValue = 0;
                table << "cell " << idx << ": observed " << o << " where expected is 0\n";
                r.table = table.str();
                return r;
            }
            continue;
        }
        if (e < minExpected || (pooledExp > 0 && pooledExp < minExpected)) {
            pooledObs += o;
            pooledExp += e;
            if (pooledExp >= minExpected) {
                addCell(pooledObs, pooledExp, "pooled");
                pooledObs = pooledExp = 0;
            }
            continue;
        }
        addCell(o, e, "cell " + std::to_string(idx));
    }
    if (pooledExp > 0) addCell(pooledObs, pooledExp, "pooled (rest)");
    r.dof = cells - 1;
    r.pValue = r.dof > 0 ? chi2Survival(r.statistic, r.dof) : 1.0;
    r.table = table.str();
    return r;
}

double sidakAlpha(double alpha, int numTests) { return 1 - std::pow(1 - alpha, 1.0 / numTests); }

}  // namespace luxplan::test
