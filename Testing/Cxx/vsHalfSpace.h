// Chandrasekhar's H function of isotropic scattering with albedo a on [0, 1], from its integral
// equation 1/H(mu) = sqrt(1 - a) + (a/2) int_0^1 mu' H(mu') / (mu + mu') dmu', by fixed-point
// iteration on a 64-point Gauss-Legendre rule (Chandrasekhar, Radiative Transfer, ch. V): the
// analytic reference of a homogeneous half-space under a uniform sky, for the Monte Carlo kernel's
// tests and the light volume's.
#ifndef vsHalfSpace_h
#define vsHalfSpace_h

#include <algorithm>
#include <cmath>
#include <vector>

namespace vstest
{
class ChandrasekharH
{
public:
  explicit ChandrasekharH(double albedo)
    : A(albedo)
  {
    const int n = 64;
    const double pi = 3.14159265358979323846;
    // Gauss-Legendre nodes on [-1, 1] by Newton's method on P_n, mapped to [0, 1].
    for (int i = 0; i < n; ++i)
    {
      double z = std::cos(pi * (i + 0.75) / (n + 0.5)), dp = 0.0;
      for (int it = 0; it < 100; ++it)
      {
        double p0 = 1.0, p1 = z;
        for (int k = 2; k <= n; ++k)
        {
          const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1.0);
        const double dz = p1 / dp;
        z -= dz;
        if (std::abs(dz) < 1e-15)
          break;
      }
      this->X.push_back(0.5 * (1.0 - z));
      this->W.push_back(1.0 / ((1.0 - z * z) * dp * dp));
    }
    this->H.assign(n, 1.0);
    for (int it = 0; it < 20000; ++it)
    {
      double change = 0.0;
      for (int i = 0; i < n; ++i)
      {
        const double v = 1.0 / this->Inverse(this->X[i]);
        change = std::max(change, std::abs(v - this->H[i]));
        this->H[i] = v;
      }
      if (change < 1e-13)
        break;
    }
  }

  double operator()(double mu) const { return 1.0 / this->Inverse(mu); }

  /** The radiance reflected towards cosine mu by the half-space under a uniform sky of radiance 1. */
  double Reflected(double mu) const { return 1.0 - std::sqrt(1.0 - this->A) * (*this)(mu); }

private:
  double Inverse(double mu) const
  {
    double s = 0.0;
    for (size_t j = 0; j < this->X.size(); ++j)
      s += this->W[j] * this->X[j] * this->H[j] / (mu + this->X[j]);
    return std::sqrt(1.0 - this->A) + 0.5 * this->A * s;
  }

  double A;
  std::vector<double> X, W, H;
};
}

#endif
