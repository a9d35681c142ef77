#include "vsBenchScene.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include <stdexcept>

namespace vstool
{
SceneObjects BuildRadianceScene(const std::string& sceneFile, int size, Scene& scene)
{
  scene = ReadSceneFile(sceneFile);
  scene.Render.Width = scene.Render.Height = size;
  scene.Environment.VisibleBackground = false;
  return BuildScene(scene);
}

void CheckRender(vtkVisibilitySweepVolumeMapper* mapper)
{
  const char* error = mapper->GetLastError();
  if (error && *error)
  {
    throw std::runtime_error(std::string("render failed: ") + error);
  }
}

std::vector<double> ImageRgb(vtkImageData* image, const char* array)
{
  std::vector<double> out;
  vtkDataArray* a = image ? image->GetPointData()->GetArray(array) : nullptr;
  if (!a)
  {
    return out;
  }
  out.reserve(size_t(a->GetNumberOfTuples()) * 3);
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      out.push_back(a->GetComponent(i, c));
    }
  }
  return out;
}

double SecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
}
