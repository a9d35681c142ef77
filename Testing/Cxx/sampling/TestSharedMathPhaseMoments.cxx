// The preview's Henyey-Greenstein phase towards the environment (sampling/phase_moments.h): the band-1
// reconstruction (1 / 4 pi)(I + 3 g M.d) of the in-scattered light against the numerical integral of
// f_HG(d.w) L(w) over the sphere, for a radiance field of known spherical-harmonic bands
//   L(w) = c0 + c1.w + c2 P2(w.z)   (P2 = (3 t^2 - 1) / 2),
// whose I = 4 pi c0 and M = (4 pi / 3) c1 are integrated numerically as well. By Funk-Hecke the exact
// value is c0 + g c1.d + g^2 c2 P2(d.z): the reconstruction must equal it without the band-2 term, to the
// quadrature's error (1e-4 relative: a 1024 x 2048 midpoint rule in (cos, phi) whose cos is refined
// towards +-d where HG peaks), for g from -0.9 to 0.9 and directions d all over the sphere; and the
// isotropic preview (c0) must be off by the band-1 term (the test can tell). The clamp: light from one
// direction only (a narrow cap) with |g| > 1/3 undershoots below 0 seen from the side the light comes
// from, and the result is 0 there, never negative; g = 0 returns I itself, bit for bit.
#include "sampling/phase_moments.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace vs::shared;

namespace
{
const double Pi = 3.14159265358979323846;

// Integral over the sphere of f(w), in coordinates (t = w.a, phi) about the unit axis a, with t's
// samples placed by t = 1 - 2 u^2 near +a and mirrored near -a (HG's peak lies along +-a).
double Integrate(const glm::dvec3& a, const std::function<double(const glm::dvec3&)>& f)
{
  glm::dvec3 u = std::abs(a.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(a, u)), e2 = glm::cross(a, e1);
  const int nt = 1024, np = 512;
  double sum = 0.0;
  for (int i = 0; i < nt; ++i)
  {
    // s in (0, 1) midpoints; t = 1 - 2 s^2 on the upper half (dt = 4 s ds), mirrored on the lower half.
    const double s = (i + 0.5) / nt;
    for (int half = 0; half < 2; ++half)
    {
      const double t = (half == 0 ? 1.0 : -1.0) * (1.0 - s * s);
      const double dt = 2.0 * s / nt;
      const double r = std::sqrt(std::max(0.0, 1.0 - t * t));
      for (int j = 0; j < np; ++j)
      {
        const double phi = 2.0 * Pi * (j + 0.5) / np;
        const glm::dvec3 w = t * a + r * (std::cos(phi) * e1 + std::sin(phi) * e2);
        sum += f(w) * dt * 2.0 * Pi / np;
      }
    }
  }
  return sum;
}

double P2(double t)
{
  return 0.5 * (3.0 * t * t - 1.0);
}
}

TEST(PhaseMoments, Band1MatchesTheIntegralOfHenyeyGreensteinUpToBand2)
{
  const double c0 = 1.0, c2 = 0.3;
  const glm::dvec3 c1(0.2, -0.35, 0.5);
  const auto L = [&](const glm::dvec3& w) { return c0 + glm::dot(c1, w) + c2 * P2(w.z); };
  // The field's moments, numerically (about z: any axis integrates them).
  const glm::dvec3 z(0, 0, 1);
  const double I = Integrate(z, L);
  const glm::dvec3 M(Integrate(z, [&](const glm::dvec3& w) { return L(w) * w.x; }),
    Integrate(z, [&](const glm::dvec3& w) { return L(w) * w.y; }),
    Integrate(z, [&](const glm::dvec3& w) { return L(w) * w.z; }));
  EXPECT_NEAR(I, 4.0 * Pi * c0, 1e-4 * 4.0 * Pi);
  EXPECT_NEAR(glm::length(M - 4.0 * Pi / 3.0 * c1), 0.0, 1e-4 * 4.0 * Pi);
  double worst = 0.0, worstIsotropic = 0.0;
  for (float g : { -0.9f, -0.6f, -0.3f, 0.3f, 0.6f, 0.9f })
    for (const glm::dvec3& d0 : { glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1), glm::dvec3(1, 1, 0), glm::dvec3(-0.3, 0.8, 0.5),
           glm::dvec3(0.6, -0.7, -0.4) })
    {
      const glm::dvec3 d = glm::normalize(d0);
      const double exact = Integrate(d, [&](const glm::dvec3& w) { return double(vs_hg_pdf(float(glm::dot(d, w)), g)) * L(w); });
      // Funk-Hecke: the integral is c0 + g c1.d + g^2 c2 P2(d.z); the quadrature must agree.
      ASSERT_NEAR(exact, c0 + g * glm::dot(c1, d) + double(g) * g * c2 * P2(d.z), 2e-4)
        << "the quadrature of f_HG, g " << g;
      const glm::vec3 band1 = vs_hg_band1_light(glm::vec3(float(I)), glm::vec3(float(M.x)), glm::vec3(float(M.y)),
        glm::vec3(float(M.z)), glm::vec3(d), g);
      const double got = band1.y / (4.0 * Pi);
      const double band2 = double(g) * g * c2 * P2(d.z);
      const double error = std::abs(got - (exact - band2)) / exact;
      worst = std::max(worst, error);
      worstIsotropic = std::max(worstIsotropic, std::abs(I / (4.0 * Pi) - (exact - band2)) / exact);
      EXPECT_LT(error, 2e-4) << "g " << g << " d " << d.x << "," << d.y << "," << d.z << ": band 1 " << got
                             << ", the integral less its band 2 " << exact - band2;
      EXPECT_EQ(band1.x, band1.y);
      EXPECT_EQ(band1.x, band1.z);
    }
  std::printf("band-1 HG against the integral less its band-2 term: worst relative %.2e; isotropic %.2e\n", worst,
    worstIsotropic);
  EXPECT_GT(worstIsotropic, 0.1) << "the isotropic reconstruction is far off: the test can tell";
}

TEST(PhaseMoments, ClampedAtZeroAndExactlyIsotropicAtZeroG)
{
  // Light from a cap of half-angle 0.1 rad around +x only: M ~ I x.
  const glm::dvec3 x(1, 0, 0);
  const double cosCap = std::cos(0.1);
  const auto cap = [&](const glm::dvec3& w) { return glm::dot(w, x) > cosCap ? 1.0 : 0.0; };
  const double I = Integrate(x, cap);
  const double Mx = Integrate(x, [&](const glm::dvec3& w) { return cap(w) * w.x; });
  const glm::vec3 Iv = glm::vec3(float(I)), mx = glm::vec3(float(Mx)), zero = glm::vec3(0.0f);
  // Seen with the light in front (d = -x: the light arrives from the camera's side), g = 0.6: band 1 gives
  // I (1 - 1.8 cos) < 0, clamped to 0; the exact value is small and positive.
  const glm::vec3 back = vs_hg_band1_light(Iv, mx, zero, zero, glm::vec3(-1, 0, 0), 0.6f);
  EXPECT_EQ(back, glm::vec3(0.0f));
  const double exact = Integrate(-x, [&](const glm::dvec3& w) { return double(vs_hg_pdf(float(-w.x), 0.6f)) * cap(w); });
  EXPECT_GT(exact, 0.0);
  EXPECT_LT(exact, 0.2 * I / (4.0 * Pi)) << "HG sends little light backwards (0.156 of isotropic at g 0.6): the clamp "
                                          "errs by at most that";
  // Seen against the light (d = +x), forward scattering: more than isotropic, never more than the exact value
  // (band 1 of a narrow lobe: I (1 + 3 g cos 0.05) against HG's peak).
  const glm::vec3 front = vs_hg_band1_light(Iv, mx, zero, zero, glm::vec3(1, 0, 0), 0.6f);
  EXPECT_GT(front.x, 2.5f * float(I));
  EXPECT_LT(front.x / (4.0 * Pi), Integrate(x, [&](const glm::dvec3& w) { return double(vs_hg_pdf(float(w.x), 0.6f)) * cap(w); }));
  // g = 0 (and below VS_HG_ISOTROPIC_G): I, bit for bit, whatever M.
  const glm::vec3 I3(0.25f, 1.5f, 3.0f), m(0.1f, -0.7f, 2.0f);
  EXPECT_EQ(vs_hg_band1_light(I3, m, m, m, glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f)), 0.0f), I3);
  EXPECT_EQ(vs_hg_band1_light(I3, m, m, m, glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f)), -0.0f), I3);
  EXPECT_EQ(vs_hg_band1_light(I3, m, m, m, glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f)), 0.5f * VS_HG_ISOTROPIC_G), I3);
  // Never negative, whatever g and d.
  for (float g : { -0.99f, -0.5f, 0.5f, 0.99f })
    for (const glm::vec3& d : { glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::normalize(glm::vec3(1, 1, 1)) })
    {
      const glm::vec3 v = vs_hg_band1_light(Iv, mx, zero, zero, d, g);
      EXPECT_GE(v.x, 0.0f);
    }
}
