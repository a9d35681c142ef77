#include "vsImageOutput.h"
#include "vsPendingFile.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkImageWriter.h"
#include "vtkJPEGWriter.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkRenderWindow.h"
#include "vtkWindowToImageFilter.h"

#include <ImfChannelList.h>
#include <ImfDoubleAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <ImfVecAttribute.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace vstool
{
namespace fs = std::filesystem;

namespace
{
std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), ::tolower);
  return s;
}

bool IsJpeg(const std::string& ext)
{
  return ext == ".jpg" || ext == ".jpeg";
}

void AddProvenance(Imf::Header& header, const ImageProvenance& p)
{
  auto text = [&header](const char* name, const std::string& value) {
    header.insert(std::string("vissweep.") + name, Imf::StringAttribute(value));
  };
  auto point = [&header](const char* name, const std::array<double, 3>& v) {
    header.insert(std::string("vissweep.") + name, Imf::V3dAttribute(Imath::V3d(v[0], v[1], v[2])));
  };
  text("version", p.Version);
  text("scene", p.SceneFile);
  if (p.TimeStep >= 0)
  {
    header.insert("vissweep.timeStep", Imf::IntAttribute(p.TimeStep));
  }
  text("mode", p.Mode);
  text("strategy", p.Strategy);
  text("effectiveStrategy", p.EffectiveStrategy);
  header.insert("vissweep.spp", Imf::IntAttribute(p.Spp));
  header.insert("vissweep.seconds", Imf::DoubleAttribute(p.Seconds));
  header.insert("vissweep.seed", Imf::IntAttribute(p.Seed));
  point("cameraPosition", p.CameraPosition);
  point("focalPoint", p.FocalPoint);
  point("viewUp", p.ViewUp);
  header.insert("vissweep.viewAngle", Imf::DoubleAttribute(p.ViewAngle));
  text("device", p.Device);
}
}

std::string Extension(const std::string& path)
{
  return Lower(fs::path(path).extension().string());
}

void CheckOutputPath(const std::string& out)
{
  const std::string ext = Extension(out);
  if (ext != ".exr" && ext != ".png" && !IsJpeg(ext))
  {
    throw std::runtime_error("-o " + out + ": unknown output format '" + ext + "' (expected .exr, .png or .jpg)");
  }
  CheckWritable("-o", out);
}

void WriteExr(vtkImageData* radiance, const std::string& path, const ImageProvenance* provenance)
{
  if (!radiance)
  {
    throw std::runtime_error("the renderer produced no radiance image");
  }
  vtkDataArray* rgb = radiance->GetPointData()->GetArray("Radiance");
  vtkDataArray* alpha = radiance->GetPointData()->GetArray("Alpha");
  if (!rgb || rgb->GetNumberOfComponents() != 3)
  {
    throw std::runtime_error("the renderer's radiance image has no 3-component 'Radiance' array");
  }
  int dims[3];
  radiance->GetDimensions(dims);
  const int w = dims[0], h = dims[1];
  std::vector<float> pixels(size_t(w) * size_t(h) * 4);
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const vtkIdType src = vtkIdType(y) * w + x;        // VTK: rows bottom-up
      const size_t dst = (size_t(h - 1 - y) * w + x) * 4; // EXR: rows top-down
      for (int c = 0; c < 3; ++c)
      {
        pixels[dst + c] = static_cast<float>(rgb->GetComponent(src, c));
      }
      pixels[dst + 3] = alpha ? static_cast<float>(alpha->GetComponent(src, 0)) : 1.0f;
    }
  }
  try
  {
    Imf::Header header(w, h);
    header.compression() = Imf::ZIP_COMPRESSION;
    if (provenance)
    {
      AddProvenance(header, *provenance);
    }
    const char* names[4] = { "R", "G", "B", "A" };
    Imf::FrameBuffer frame;
    for (int c = 0; c < 4; ++c)
    {
      header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
      frame.insert(names[c],
        Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(pixels.data() + c), sizeof(float) * 4, sizeof(float) * 4 * w));
    }
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(h);
  }
  catch (const std::exception& e)
  {
    throw std::runtime_error("cannot write EXR '" + path + "': " + e.what());
  }
}

void WriteWindowImage(vtkRenderWindow* window, const std::string& path)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ShouldRerenderOff(); // a re-render would add samples
  grab->SetInputBufferTypeToRGB();
  grab->Update();
  const bool jpeg = IsJpeg(Extension(path));
  vtkSmartPointer<vtkImageWriter> writer;
  if (jpeg)
  {
    auto j = vtkSmartPointer<vtkJPEGWriter>::New();
    j->SetQuality(95);
    j->ProgressiveOff();
    writer = j;
  }
  else
  {
    writer = vtkSmartPointer<vtkPNGWriter>::New();
  }
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(path.c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    throw std::runtime_error(std::string("cannot write ") + (jpeg ? "JPEG '" : "PNG '") + path + "'");
  }
}
}
