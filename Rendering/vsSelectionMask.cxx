#include "vsSelectionMask.h"

#include "vtkHardwareSelector.h"

namespace vs
{
std::vector<float> SelectionMask::Image(vtkHardwareSelector* selector, const std::vector<float>& rgba)
{
  std::vector<float> image(rgba.size(), 0.0f);
  const int pass = selector ? selector->GetCurrentPass() : -1;
  if (pass != vtkHardwareSelector::ACTOR_PASS && pass != vtkHardwareSelector::PROCESS_PASS)
  {
    return image;
  }
  float color[3] = { 0.0f, 0.0f, 0.0f };
  selector->GetPropColorValue(color); // set by BeginRenderProp for these passes
  for (size_t i = 0; i + 3 < rgba.size(); i += 4)
  {
    if (rgba[i + 3] > Threshold)
    {
      image[i] = color[0];
      image[i + 1] = color[1];
      image[i + 2] = color[2];
      image[i + 3] = 1.0f;
    }
  }
  return image;
}

bool SelectionMask::AsksForIds(vtkHardwareSelector* selector)
{
  const int pass = selector ? selector->GetCurrentPass() : -1;
  return pass == vtkHardwareSelector::POINT_ID_LOW24 || pass == vtkHardwareSelector::POINT_ID_HIGH24 ||
    pass == vtkHardwareSelector::CELL_ID_LOW24 || pass == vtkHardwareSelector::CELL_ID_HIGH24;
}

bool SelectionMask::AsksForCellIds(vtkHardwareSelector* selector)
{
  const int pass = selector ? selector->GetCurrentPass() : -1;
  return pass == vtkHardwareSelector::CELL_ID_LOW24 || pass == vtkHardwareSelector::CELL_ID_HIGH24;
}

std::vector<float> SelectionMask::IdImage(vtkHardwareSelector* selector, const std::vector<vtkIdType>& ids)
{
  std::vector<float> image(4 * ids.size(), 0.0f);
  const int pass = selector ? selector->GetCurrentPass() : -1;
  const bool high = pass == vtkHardwareSelector::POINT_ID_HIGH24 || pass == vtkHardwareSelector::CELL_ID_HIGH24;
  for (size_t i = 0; i < ids.size(); ++i)
  {
    if (ids[i] >= 0)
    {
      float color[3];
      vtkHardwareSelector::Convert(high ? (ids[i] >> 24) & 0xffffff : ids[i] & 0xffffff, color);
      image[4 * i] = color[0];
      image[4 * i + 1] = color[1];
      image[4 * i + 2] = color[2];
      image[4 * i + 3] = 1.0f;
    }
  }
  return image;
}

long SelectionMask::Covered(const std::vector<float>& rgba)
{
  long n = 0;
  for (size_t i = 3; i < rgba.size(); i += 4)
  {
    n += rgba[i] > Threshold ? 1 : 0;
  }
  return n;
}
}
