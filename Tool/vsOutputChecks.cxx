#include "vsOutputChecks.h"
#include "vsImageOutput.h"
#include "vsPendingFile.h"
#include "vsSceneBuild.h"

#include "vtkCamera.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

#include <array>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <system_error>

namespace vstool
{
namespace fs = std::filesystem;

namespace
{
// The file a path names, for comparing outputs: absolute, normalised, symbolic links of its folder
// resolved (the file itself may not exist yet).
std::string Identity(const std::string& path)
{
  std::error_code ec;
  fs::path p = fs::absolute(fs::path(path), ec).lexically_normal();
  const fs::path dir = fs::weakly_canonical(p.parent_path(), ec);
  return ec ? p.string() : (dir / p.filename()).string();
}
}

void CheckOutputs(const std::vector<std::string>& images, const std::string& json)
{
  std::map<std::string, std::string> seen; // identity -> how it was given
  auto distinct = [&seen](const std::string& option, const std::string& path) {
    const auto [it, added] = seen.emplace(Identity(path), option + " " + path);
    if (!added)
    {
      throw std::runtime_error(option + " " + path + ": the same file as " + it->second +
        "; give each output its own file");
    }
  };
  for (const auto& out : images)
  {
    CheckOutputPath(out);
    distinct("-o", out);
  }
  if (!json.empty() && json != "-")
  {
    CheckWritable("--json", json);
    distinct("--json", json);
  }
}

void CheckOutputsForMode(const std::vector<std::string>& images, const std::string& mode)
{
  if (mode != "ambient-occlusion" && mode != "emission-absorption")
  {
    return;
  }
  for (const auto& out : images)
  {
    if (Extension(out) == ".exr")
    {
      throw std::runtime_error("-o " + out + ": the " + mode +
        " mode computes no radiance for an EXR (only the Monte Carlo and preview modes do); write a .png");
    }
  }
}

void CheckVolumeInView(SceneObjects& objects)
{
  vtkRenderer* ren = objects.Renderer;
  double b[6];
  objects.Volume->GetBounds(b);
  if (!(b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5]))
  {
    return; // no bounds: the mapper says why when it renders
  }
  const int* size = objects.Window->GetSize();
  const double aspect = size[1] > 0 ? double(size[0]) / size[1] : 1.0;
  std::array<double, 24> planes; // left, right, bottom, top, near, far: a x + b y + c z + d >= 0 inside
  ren->GetActiveCamera()->GetFrustumPlanes(aspect, planes.data());
  for (int p = 0; p < 4; ++p) // the sides (near and far follow the volume: the tool resets the range)
  {
    const double* q = &planes[size_t(4 * p)];
    bool outside = true;
    for (int c = 0; c < 8 && outside; ++c)
    {
      const double x = b[c & 1], y = b[2 + ((c >> 1) & 1)], z = b[4 + ((c >> 2) & 1)];
      outside = q[0] * x + q[1] * y + q[2] * z + q[3] < 0.0;
    }
    if (outside)
    {
      vtkCamera* cam = ren->GetActiveCamera();
      const double* pos = cam->GetPosition();
      const double* fp = cam->GetFocalPoint();
      throw std::runtime_error("the camera (position " + std::to_string(pos[0]) + ", " + std::to_string(pos[1]) + ", " +
        std::to_string(pos[2]) + ", focal point " + std::to_string(fp[0]) + ", " + std::to_string(fp[1]) + ", " +
        std::to_string(fp[2]) + ") sees none of the volume (bounds " + std::to_string(b[0]) + ".." +
        std::to_string(b[1]) + ", " + std::to_string(b[2]) + ".." + std::to_string(b[3]) + ", " +
        std::to_string(b[4]) + ".." + std::to_string(b[5]) + "): point it at the volume");
    }
  }
}
}
