// Issue 39: the preview models the phase's anisotropy (ScatteringAnisotropy g) towards the environment, up to
// band 1 of its spherical-harmonic expansion (sampling/phase_moments.h, the light volume's band-1 moment).
//  - A ball (one scattering event, so that the preview's isotropic higher orders do not blur the comparison)
//    under a wide sun behind it and to the side, plus a dim sky: with g = 0.6 and g = -0.6 the preview's mean
//    radiance lies within 10% and 25% of the converged Monte Carlo estimate's (1024 spp), and the isotropic
//    preview's is more than twice as far and at least 25% off (the test can tell). The backward bound is the
//    wider: the preview takes the light as one HG lobe (phase_moments.h), which sends too little of a sun's
//    light backwards. Measured (loaded machine, lavapipe): printed by the test, quoted in docs/reference.md.
//  - The light volume is built again when g becomes non-zero (to make the moment), not for another non-zero g,
//    not for g back to 0 (the moment is kept, unread), and never for a camera move.
//  - g = 0 is the isotropic preview, bit for bit, before and after a round trip through g != 0.
//  - Under full transport (1024 events: the light volume's orders >= 2 carried in the similar medium of g, their
//    band-1 moment read at the preview's last event) the preview's mean lies within 10% of the estimate's at
//    g = 0.6 (the build before: -20%, it fails) and 25% at g = -0.6 (the first order's lobe, as above); another
//    g builds the light volume again, a camera move does not, and g = 0 is the preview of before bit for bit.
#include "vsLitBallScene.h"
#include "vtkEnvironmentMapSource.h"

#include "vtkCamera.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using vstest::Check;
using vstest::Mean;

namespace
{
// The lights tests' ball (vsLitBallScene.h), thinner (peak opacity 0.4), in the preview at one event, under a
// wide sun behind it (the camera looks along -z) and to its side, over a dim sky.
struct Scene : vstest::LitBallScene
{
  vtkNew<vtkEnvironmentMapSource> Environment;

  Scene()
    : LitBallScene(0.4)
  {
    this->Environment->SetTypeToSunDisk();
    this->Environment->SetOctahedralSize(64);
    this->Environment->SetSunDirection(0.6, 0.2, -1.0);
    this->Environment->SetSunAngularRadius(30.0);
    this->Environment->SetSunRadiance(4.0, 4.0, 4.0);
    this->Environment->SetSkyColor(0.2, 0.2, 0.2);
    this->Mapper->SetEnvironmentConnection(this->Environment->GetOutputPort());
    this->Mapper->SetRenderModeToPreview();
    this->Mapper->SetMaximumScatteringEvents(1);
    this->Mapper->SetVoxelsPerCell(2.0); // cells of 2 voxels: less of the light volume's interpolation bias
  }
};
}

int TestMapperPreviewAnisotropy(int, char*[])
{
  Scene s;
  const std::vector<float> isotropic = s.Preview();
  const int builds0 = s.Mapper->GetLightVolumeBuildCount();

  s.Mapper->SetScatteringAnisotropy(0.6);
  const std::vector<float> forward = s.Preview();
  Check(s.Mapper->GetLightVolumeBuildCount() == builds0 + 1, "g from 0 to 0.6 builds the light volume (its moment)");
  s.Renderer->GetActiveCamera()->Azimuth(30.0);
  s.Preview();
  Check(s.Mapper->GetLightVolumeBuildCount() == builds0 + 1, "a camera move builds no light volume");
  s.Renderer->GetActiveCamera()->Azimuth(-30.0);
  s.Mapper->SetScatteringAnisotropy(-0.6);
  const std::vector<float> backward = s.Preview();
  Check(s.Mapper->GetLightVolumeBuildCount() == builds0 + 1, "another non-zero g builds nothing (the same moment)");
  s.Mapper->SetScatteringAnisotropy(0.0);
  const std::vector<float> again = s.Preview();
  Check(s.Mapper->GetLightVolumeBuildCount() == builds0 + 1, "g back to 0 builds nothing");
  Check(again == isotropic, "g = 0 is the isotropic preview, bit for bit, after a round trip through g != 0");
  Check(forward != isotropic && backward != isotropic, "g != 0 changes the preview");

  // Against the converged estimate (1024 spp).
  const double m0 = Mean(s.Estimate(1024));
  s.Mapper->SetScatteringAnisotropy(0.6);
  const double mf = Mean(s.Estimate(1024));
  s.Mapper->SetScatteringAnisotropy(-0.6);
  const double mb = Mean(s.Estimate(1024));
  const double iso = Mean(isotropic), pf = Mean(forward), pb = Mean(backward);
  // The preview's bias at g = 0 is the light volume's (its interpolation between cells on this small ball,
  // docs/reference.md "The light volume"); what the phase adds is the bias at g against that at 0: the
  // preview's relative change from g = 0 against the estimate's.
  const double b0 = iso / m0 - 1.0, bf = pf / mf - 1.0, bb = pb / mb - 1.0;
  const double af = (pf / iso) / (mf / m0) - 1.0, ab = (pb / iso) / (mb / m0) - 1.0;
  const double isoF = (m0 / mf) - 1.0, isoB = (m0 / mb) - 1.0;
  std::printf("g 0: estimate %.5f, preview %.5f (%+.1f%%)\n", m0, iso, 100.0 * b0);
  std::printf("g 0.6: estimate %.5f, preview %.5f (%+.1f%%; against g = 0 %+.1f%%), isotropic preview %+.1f%% "
              "(against g = 0 %+.1f%%)\n",
    mf, pf, 100.0 * bf, 100.0 * af, 100.0 * (iso / mf - 1.0), 100.0 * isoF);
  std::printf("g -0.6: estimate %.5f, preview %.5f (%+.1f%%; against g = 0 %+.1f%%), isotropic preview %+.1f%% "
              "(against g = 0 %+.1f%%)\n",
    mb, pb, 100.0 * bb, 100.0 * ab, 100.0 * (iso / mb - 1.0), 100.0 * isoB);
  Check(mf > 1.2 * m0 && mb < 0.8 * m0, "the estimate: the sun behind the ball brightens it with g 0.6, darkens "
                                        "it with g -0.6 (the scene tells the phases apart)");
  Check(std::abs(bf) < 0.10, "g 0.6: the preview's mean within 10% of the estimate's");
  Check(std::abs(bb) < 0.25, "g -0.6: the preview's mean within 25% of the estimate's");
  Check(std::abs(iso / mf - 1.0) > 2.0 * std::abs(bf) && std::abs(iso / mf - 1.0) > 0.25,
    "g 0.6: the isotropic preview is far off (the test can tell)");
  Check(std::abs(iso / mb - 1.0) > 2.0 * std::abs(bb) && std::abs(iso / mb - 1.0) > 0.25,
    "g -0.6: the isotropic preview is far off (the test can tell)");
  Check(std::string(s.Mapper->GetLastError()).empty(), std::string("no error: ") + s.Mapper->GetLastError());

  // Full transport (MaximumScatteringEvents 1024, the orders >= 2 in the similar medium of g and their band-1
  // moment at the preview's last event; vsLightVolume.h): the same ball and sun.
  Scene f;
  f.Mapper->SetMaximumScatteringEvents(1024);
  const std::vector<float> full0 = f.Preview();
  const int fullBuilds = f.Mapper->GetLightVolumeBuildCount();
  const double gs[3] = { 0.0, 0.6, -0.6 };
  double pm[3], em[3];
  for (int i = 0; i < 3; ++i)
  {
    f.Mapper->SetScatteringAnisotropy(gs[i]);
    pm[i] = Mean(f.Preview());
    if (i == 1)
    {
      f.Renderer->GetActiveCamera()->Azimuth(30.0);
      f.Preview();
      f.Renderer->GetActiveCamera()->Azimuth(-30.0);
      Check(f.Mapper->GetLightVolumeBuildCount() == fullBuilds + 1,
        "full transport: g from 0 to 0.6 builds the light volume once, a camera move not again");
    }
    em[i] = Mean(f.Estimate(1024));
    std::printf("full transport, g %.1f: estimate %.5f, preview %.5f (%+.1f%%)\n", gs[i], em[i], pm[i],
      100.0 * (pm[i] / em[i] - 1.0));
  }
  Check(f.Mapper->GetLightVolumeBuildCount() == fullBuilds + 2,
    "full transport: another g builds again (the orders >= 2 depend on g's value)");
  f.Mapper->SetScatteringAnisotropy(0.0);
  Check(f.Preview() == full0, "full transport: g = 0 is the preview of before, bit for bit, after g != 0");
  // The bounds: the build before (isotropic orders >= 2) measured -20.0% at g 0.6 (it fails here) and -12.5%
  // at g -0.6, where its isotropic orders' excess cancelled part of the first order's deficit (the lobe's, -16.6%
  // above); now +-0.6 give -1.5% and -19.9% (loaded machine, docs/reference.md).
  Check(std::abs(pm[1] / em[1] - 1.0) < 0.10, "full transport, g 0.6: the preview's mean within 10% of the estimate's");
  Check(std::abs(pm[2] / em[2] - 1.0) < 0.25, "full transport, g -0.6: the preview's mean within 25% of the estimate's");
  Check(std::string(f.Mapper->GetLastError()).empty(), std::string("no error: ") + f.Mapper->GetLastError());
  return vstest::ExitCode();
}
