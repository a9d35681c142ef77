// vsPreviewHandOver.h — the hand-over from the interactive preview to the Monte Carlo accumulation
// once the view is still (issue 15). The preview P is noise-free but biased (the light volume's
// resolution); the Monte Carlo mean M_N of N samples is unbiased with variance v / N per pixel. Of
// the blends (1 - s) M_N + s P, the one of least expected squared error has
//   s = V / (V + B),   V = mean over pixels of v / N,   B = the preview's squared bias,
// and B is measured from the two images themselves: E[(P - M_N)^2] = B + V, so B = mean (P - M_N)^2 - V
// (clamped at 0). The first still frame shows almost the preview (N small, V large), the share falls
// as the samples come in, and the hand-over ends (s = 0 from then on) once s < EndShare: the
// accumulated image is then shown as it is, unbiased. Not wrapped.
#ifndef vsPreviewHandOver_h
#define vsPreviewHandOver_h

#include <cstdint>
#include <vector>

namespace vs
{
class PreviewHandOver
{
public:
  /** Below this share the hand-over ends: the preview's last step is then at most 5% of the
   *  difference between the two images, and the shown image is the estimate itself. */
  static constexpr double EndShare = 0.05;

  /** The preview's share s (above) for the preview `preview` and the Monte Carlo mean `mean` (rgba
   *  per pixel, the same size), `variance` the mean's per-sample variance (rgba per pixel, double) and
   *  `samples` its sample count. rgb only (alpha is coverage). 1 with fewer than 2 samples (no
   *  variance estimate yet); 0 when the two images agree exactly and the mean has no variance, or a
   *  sum is not finite. */
  static double PreviewShare(const std::vector<float>& preview, const std::vector<float>& mean,
    const std::vector<double>& variance, uint32_t samples);

  /** The largest share `seconds` after the hand-over began, for a hand-over of `duration` seconds:
   *  1 - seconds / duration, clamped to [0, 1] (0 for a duration of 0 or less). The blend of least
   *  expected error keeps a close preview for hundreds of samples; this bounds how long it is shown. */
  static double ShareCap(double seconds, double duration);

  /** mean = (1 - share) mean + share preview, every channel. */
  static void Blend(std::vector<float>& mean, const std::vector<float>& preview, double share);
};
}

#endif
