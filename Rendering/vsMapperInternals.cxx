#include "vsMapperInternals.h"

#include "vtkRenderWindow.h"

#include <algorithm>

// Makes `ren`'s accumulator the current one: the current view's state goes to OtherViews, ren's
// comes back from there (or starts empty). Views whose renderer was deleted are forgotten.
void vtkVisibilitySweepVolumeMapper::Internals::SwitchView(vtkRenderer* ren)
{
  if (this->HasCurrentView && this->CurrentView.GetPointer() == ren)
  {
    return;
  }
  if (this->HasCurrentView && this->CurrentView)
  {
    View v;
    v.Renderer = this->CurrentView;
    v.MC = std::move(this->MC);
    v.MCGrid = std::move(this->MCGrid);
    v.Interactive = std::move(this->Interactive);
    v.ImageSignature = std::move(this->ImageSignature);
    v.Selector = this->Selector;
    v.GridGeneration = this->GridGeneration();
    this->OtherViews.push_back(std::move(v));
  }
  this->OtherViews.erase(std::remove_if(this->OtherViews.begin(), this->OtherViews.end(),
                           [](const View& v) { return !v.Renderer; }),
    this->OtherViews.end());
  this->MC.reset();
  this->MCGrid.reset();
  this->Interactive.reset();
  this->ImageSignature.clear();
  this->HandOver = PreviewImage();
  this->Selector = vs::StrategySelector();
  for (auto it = this->OtherViews.begin(); it != this->OtherViews.end(); ++it)
  {
    if (it->Renderer.GetPointer() == ren)
    {
      this->MC = std::move(it->MC);
      this->MCGrid = std::move(it->MCGrid);
      this->Interactive = std::move(it->Interactive);
      this->ImageSignature = std::move(it->ImageSignature);
      this->Selector = it->Selector;
      if (it->GridGeneration != this->GridGeneration())
      {
        this->Selector.ResetGrid(); // a new grid arrived while another view rendered
      }
      this->OtherViews.erase(it);
      break;
    }
  }
  this->CurrentView = ren;
  this->HasCurrentView = true;
}

// Forgets the views shown in `win` (and those whose renderer is gone); returns whether views in
// other windows remain, which keep the shared device state (volume, grid, environment).
bool vtkVisibilitySweepVolumeMapper::Internals::ReleaseViewsOf(vtkWindow* win)
{
  auto inWindow = [win](vtkRenderer* r) { return !r || static_cast<vtkWindow*>(r->GetRenderWindow()) == win; };
  this->OtherViews.erase(std::remove_if(this->OtherViews.begin(), this->OtherViews.end(),
                           [&](const View& v) { return inWindow(v.Renderer); }),
    this->OtherViews.end());
  if (this->HasCurrentView && inWindow(this->CurrentView))
  {
    this->MC.reset();
    this->MCGrid.reset();
    this->Interactive.reset();
    this->ImageSignature.clear();
    this->HandOver = PreviewImage();
    this->Selector = vs::StrategySelector();
    this->CurrentView = nullptr;
    this->HasCurrentView = false;
  }
  return this->HasCurrentView || !this->OtherViews.empty();
}
