#include "swarm/measure/fit.h"

#include <cmath>

#include "math/portable_math.h"

namespace swarm {

PowerLawFit fit_power_law(const std::vector<double>& x, const std::vector<double>& y) {
  PowerLawFit f;
  std::vector<double> lx, ly;
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
    if (x[i] > 0 && y[i] > 0 && std::isfinite(x[i]) && std::isfinite(y[i])) {
      lx.push_back(portable::log(x[i]));
      ly.push_back(portable::log(y[i]));
      f.used.push_back(int(i));
    }
  }
  const std::size_t n = lx.size();
  if (n < 3) return f;
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) mx += lx[i], my += ly[i];
  mx /= n;
  my /= n;
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (lx[i] - mx) * (lx[i] - mx);
    sxy += (lx[i] - mx) * (ly[i] - my);
    syy += (ly[i] - my) * (ly[i] - my);
  }
  if (sxx <= 0) return f;
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  double ss_res = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = ly[i] - (f.intercept + f.slope * lx[i]);
    f.residuals.push_back(r);
    ss_res += r * r;
  }
  f.r_squared = syy > 0 ? 1 - ss_res / syy : 1.0;
  f.slope_stderr = std::sqrt(ss_res / double(n - 2) / sxx);
  f.valid = true;
  return f;
}

}  // namespace swarm
